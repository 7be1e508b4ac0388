// Output: every VTK/<case>_<n>.vtu holds the display fields and the full state (every restart
// field and run scalar of the registries, the function objects' state), so `startFrom
// latestTime;` continues bit-identically to an uninterrupted run (SimulationRestart.cpp).
#include "solver/Simulation.hpp"

#include "core/CommandLine.hpp"
#include "core/InputError.hpp"
#include "io/AtomicFile.hpp"
#include "io/PvtuFile.hpp"
#include "io/VtuFile.hpp"

#include <nlohmann/json.hpp>

#include <omp.h>

#include <numeric>
#include <optional>
#include <sstream>


namespace sph
{

// Typed JSON (numbers as numbers), so that e.g. jq '.functions.energy.maxDrift < 1e-3' works;
// a non-finite result is written as null.
template <int D>
void Simulation<D>::writeSummary(const RunSummary& summary, const std::string& failure) const
{
    if (comm_.rank() != 0)
    {
        return; // one summary, of the whole run
    }
    nlohmann::ordered_json json;
    json["case"] = caseName_;
    // What made the run: the build and the command line (to run it again).
    json["version"] = projectVersion();
    json["gitRevision"] = gitRevision();
    json["commandLine"] = processCommandLine();
    json["dimension"] = D;
    json["particles"] = distributed() ? globalCount_ : particles_.size();
    json["spacing"] = spacing_;
    json["kernel"] = kernel_->summary();
    json["hOverDx"] = kernel_->hOverDx();
    json["formulation"] = formulation_->summary();
    json["stabilisation"] = scheme_->summary();
    json["contact"] = contact_->summary();
    json["artificialViscosity"] = viscosity_->summary();
    json["timeIntegration"] = integrator_->summary();
    json["courant"] = control_.courant;
    json["status"] = !failure.empty() ? "failed" : stoppedBy_.empty() ? "finished" : "stopped";
    json["failure"] = failure;
    json["stoppedBy"] = stoppedBy_; // "SIGTERM", "SIGINT", "stopAt writeNow"; "" otherwise
    json["endTime"] = control_.endTime;
    json["time"] = time_;
    json["steps"] = summary.steps;
    json["threads"] = omp_get_max_threads();
    json["ranks"] = comm_.size();
    json["wallSeconds"] = summary.wallSeconds;
    json["particleStepsPerSecond"] = summary.particleStepsPerSecond;
    json["outputSeconds"] = summary.outputSeconds;
    json["computeParticleStepsPerSecond"] = summary.computeParticleStepsPerSecond;
    json["peakMemoryMB"] = summary.peakMemoryMB;
    json["functions"] = nlohmann::ordered_json::object();
    for (const auto& object : functionObjects_)
    {
        auto& results = json["functions"][object->name()];
        results = nlohmann::ordered_json::object();
        for (const auto& [key, value] : object->results())
        {
            results[key] = value;
        }
        for (const auto& [key, value] : object->textResults())
        {
            results[key] = value;
        }
    }
    writeTextAtomically(dicts_.caseDir() / "postProcessing" / "summary.json", json.dump(4) + "\n");
}

template <int D>
void Simulation<D>::removeOldOutput()
{
    const std::filesystem::path folder = dicts_.caseDir() / "VTK";
    if (comm_.rank() == 0 && std::filesystem::is_directory(folder))
    {
        // The outputs of a serial run (.vtu) and of a distributed one (.pvtu and its pieces).
        std::vector<std::filesystem::path> old;
        for (const auto& file : std::filesystem::directory_iterator(folder))
        {
            if (outputIndexOf(file.path().filename().string(), caseName_) >= 0)
            {
                old.push_back(file.path());
            }
        }
        for (const auto& path : old)
        {
            std::filesystem::remove_all(path);
        }
    }
    if (comm_.rank() == 0)
    {
        std::error_code ec;
        std::filesystem::remove(pvd_.file(), ec);
    }
    pvd_ = PvdSeries(pvd_.file());
}

namespace
{

// x as written: the positions of the level being written (the current one, or the last good
// one after a failure); a restart reads them back into the particles' own x.
template <int D>
class WrittenPositions final : public FieldArray
{
public:
    WrittenPositions(const std::vector<Vec<D>>* const& written, std::vector<Vec<D>>& x)
        : written_(written), x_(x)
    {
    }
    std::size_t size() const override { return x_.size(); }
    void get(std::size_t a, double* out) const override { fieldValues::get((*written_)[a], out); }
    void set(std::size_t a, const double* in) override { fieldValues::set(in, x_[a]); }
    void resize(std::size_t n) override { x_.resize(n, Vec<D>::Zero()); }
    bool stored() const override { return true; }

private:
    const std::vector<Vec<D>>* const& written_;
    std::vector<Vec<D>>& x_;
};

} // namespace

template <int D>
void Simulation<D>::declareFields()
{
    ParticleSet<D>& p = particles_;
    ParticleFields<D>& f = fields_;
    writtenX_ = &p.x;
    f.bindArray(FieldSpec::vector(positionField, "current position x^n [m] (the VTK points)")
                    .restart()
                    .display(),
                std::make_unique<WrittenPositions<D>>(writtenX_, p.x));
    f.template derive<Vec<D>>(FieldSpec::vector("displacement", "x^n - X [m]").display().active(),
                              [this](std::size_t a) {
                                  return Vec<D>((*writtenX_)[a] - particles_.X[a]);
                              });
    f.bind(FieldSpec::vector("velocity", "velocity v^n at the time level [m/s]").display(),
           velocitySync_);
    f.bind(FieldSpec::tensor("deformationGradient", "F at x^n (2D, 1D: F_zz = 1 shown)")
               .display()
               .padding(TensorPadding::identity),
           p.F, Mat<D>::Identity());
    f.bind(FieldSpec::tensor("firstPiolaKirchhoffStress",
                             "P(F) [Pa] (2D, 1D: the components the model computes, others 0)")
               .display(),
           p.P);
    f.template derive<Mat<D>>(FieldSpec::tensor("cauchyStress", "sigma = P F^T / det F [Pa] (2D, "
                                                                "1D: the components the model "
                                                                "computes)")
                                  .display()
                                  .active(),
                              [&p](std::size_t a) {
                                  return Mat<D>(p.P[a] * p.F[a].transpose() / p.F[a].determinant());
                              });
    f.template derive<double>(
        FieldSpec::scalar("volumeRatio", "J = det F, the volume change").display().active(),
        [&p](std::size_t a) { return p.F[a].determinant(); });
    f.bind(FieldSpec::integer("bodyId", "the particle's body: index into the field data "
                                        "'bodyNames'")
               .display(),
           p.body);
    f.bind(FieldSpec::integer("fixed", "1: position held by a constraint").restart().display(),
           p.fixed);
    f.bind(FieldSpec::vector("initialPosition", "X, the position at t = 0 [m]").restart(), p.X);
    f.bind(FieldSpec::scalar("initialVolume", "V0 [m^D]").restart(), p.V0);
    f.bind(FieldSpec::scalar("mass", "m = rho0 V0 [kg]").restart(), p.m);
    f.bind(FieldSpec::vector("acceleration", "a^n = T/m + g [m/s^2]"), acceleration_);
    f.bind(FieldSpec::vector("previousPosition", "x of the last good level [m]"), previousX_);
    f.bind(FieldSpec::tensor("nextDeformationGradient", "F of the force evaluation under way"),
           nextF_, Mat<D>::Identity());
    f.bind(FieldSpec::tensor("nextStress", "P of the force evaluation under way [Pa]"), nextP_);
    if (splitKick_)
    {
        closingForce_.assign(p.size(), Vec<D>::Zero());
        f.bind(FieldSpec::vector("closingForce", "the forces of the reference before this "
                                                 "level's move, then their difference from the "
                                                 "level's (splitKick) [N]"),
               closingForce_);
    }
    if (contact_->active())
    {
        f.bind(FieldSpec::vector("contactVelocityChange", "the last contact kick [m/s]"),
               contactDeltaV_);
    }
    integrator_->attach(p.v, fields_, runScalars_);
    reference_->declareFields(fields_, runScalars_);
    audit_.declareState(runScalars_, walls_->names());
    if (moveEnergyWanted_)
    {
        audit_.declareMoveEnergy(runScalars_);
    }
    if (viscosity_->active())
    {
        audit_.declareViscousWork(runScalars_);
    }
    if (damping_)
    {
        f.bind(FieldSpec::vector("dampedVelocity", "the half-step velocity the last reset of "
                                                   "kinetic damping removed [m/s]"),
               dampingDeltaV_);
        damping_->declareState(runScalars_);
        audit_.declareDamping(runScalars_);
    }
    if (historyMaterials_)
    {
        audit_.declareDissipation(runScalars_);
        scheme_->declareHistory(materials_, fields_);
    }
    if (comm_.parallel())
    {
        // A distributed run: each particle's index in constant/particles.vtu travels with it,
        // and the pieces show which rank owns it.
        globalId_.resize(p.size());
        std::iota(globalId_.begin(), globalId_.end(), 0);
        f.bind(FieldSpec::integer("globalId", "the particle's index in constant/particles.vtu")
                   .restart()
                   .display(),
               globalId_);
        f.template derive<int>(FieldSpec::integer("rank", "the MPI rank that owns the particle")
                                   .display(),
                               [this](std::size_t) { return comm_.rank(); });
    }
    runScalars_.bind("outputIndex", outputIndex_);
    runScalars_.bind("nextOutputTime", outputSchedule_.next());
}

template <int D>
void Simulation<D>::writeOutput(const LevelView& level, const FunctionState& functionState)
{
    // The points are written from level.x (the pieces are made while the file is written).
    struct RestoreWrittenX
    {
        const std::vector<Vec<D>>*& written;
        const std::vector<Vec<D>>* current;
        ~RestoreWrittenX() { written = current; }
    } restore{writtenX_, &particles_.x};
    writtenX_ = level.x;
    // A distributed run writes its owned particles.
    std::vector<std::size_t> ownedParticles;
    for (std::size_t a = 0; distributed() && a < owned_.size(); ++a)
    {
        if (owned_[a])
        {
            ownedParticles.push_back(a);
        }
    }
    VtuData header;
    writeStateHeader<D>(fields_, runScalars_, level.time, header,
                        distributed() ? &ownedParticles : nullptr);
    // What identifies the output itself (the level it holds, whether a restart may use it).
    const auto number = [](double value) { return VtuArray{1, {value}, false, {}, {}}; };
    header.fieldData[std::string(restartPrefix) + "step"] = number(static_cast<double>(level.step));
    header.fieldData[std::string(restartPrefix) + "restartable"] = number(level.restartable ? 1.0 : 0.0);
    header.fieldData[std::string(restartPrefix) + "dimension"] = number(D);
    for (const auto& [key, value] : functionState)
    {
        header.fieldData[restartPrefix + key] = number(value);
    }
    header.stringFields["bodyNames"] = bodyNames_;

    if (distributed())
    {
        writePieces(header, ownedParticles, level.time);
    }
    else
    {
        const std::string name = caseName_ + "_" + std::to_string(outputIndex_) + ".vtu";
        writeVtuInPieces(dicts_.caseDir() / "VTK" / name, header, particles_.size(),
                         [this](std::size_t begin, std::size_t end, VtuData& piece) {
                             writeStatePoints<D>(fields_, nullptr, begin, end, piece);
                         });
        pvd_.add(level.time, name);
        lastOutputFile_ = name;
    }
    ++outputIndex_;
    if (control_.purgeWrite > 0 && comm_.rank() == 0)
    {
        // purgeWrite N: the series drops its oldest entries first, then their files go (a
        // distributed output's pieces with its .pvtu).
        const auto dropped = pvd_.keepLast(static_cast<std::size_t>(control_.purgeWrite));
        if (!dropped.empty())
        {
            pvd_.write();
            for (const std::string& file : dropped)
            {
                const std::filesystem::path path = dicts_.caseDir() / "VTK" / file;
                std::error_code ec;
                std::filesystem::remove(path, ec);
                if (path.extension() == ".pvtu")
                {
                    std::filesystem::remove_all(path.parent_path() / path.stem(), ec);
                }
            }
        }
    }
}

template class Simulation<1>;
template class Simulation<2>;
template class Simulation<3>;

} // namespace sph
