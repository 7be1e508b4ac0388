// Output and restart: every VTK/<case>_<n>.vtu holds the full state (positions, both
// velocities, reference configuration, time-step state, function-object state), so
// `startFrom latestTime;` continues bit-identically to an uninterrupted run.
#include "solver/Simulation.hpp"

#include "core/InputError.hpp"
#include "io/AtomicFile.hpp"
#include "io/VtuFile.hpp"

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <omp.h>

#include <sstream>


namespace sph
{

namespace
{

// The output index of `fileName` if it is one of this case's outputs "<case>_<n>.vtu", else -1.
long outputIndexOf(const std::string& fileName, const std::string& caseName)
{
    const std::string prefix = caseName + "_";
    const std::string suffix = ".vtu";
    if (fileName.size() <= prefix.size() + suffix.size() || fileName.rfind(prefix, 0) != 0 ||
        fileName.compare(fileName.size() - suffix.size(), suffix.size(), suffix) != 0)
    {
        return -1;
    }
    const std::string digits =
        fileName.substr(prefix.size(), fileName.size() - prefix.size() - suffix.size());
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos)
    {
        return -1;
    }
    return std::stol(digits);
}

// Display arrays: single precision, embedded in 3D (3 or 9 components) as ParaView expects.
// Restart arrays: double precision with the case's own D or D*D components.
template <int D>
VtuArray displayVectors(const std::vector<Vec<D>>& values)
{
    VtuArray array{3, {}, false, {}, {}};
    array.singles.reserve(3 * values.size());
    for (const auto& v : values)
    {
        for (int d = 0; d < 3; ++d)
        {
            array.singles.push_back(d < D ? static_cast<float>(v[d]) : 0.0f);
        }
    }
    return array;
}

// D×D matrices embedded in 3×3 (plane strain: F_zz = 1; stresses: the in-plane part).
template <int D>
VtuArray displayMatrices(const std::vector<Mat<D>>& values, bool identityPadding)
{
    VtuArray array{9, {}, false, {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"}, {}};
    array.singles.reserve(9 * values.size());
    for (const auto& m : values)
    {
        const Eigen::Matrix3d full = embed<D>(m, identityPadding);
        for (int i = 0; i < 3; ++i)
        {
            for (int j = 0; j < 3; ++j)
            {
                array.singles.push_back(static_cast<float>(full(i, j)));
            }
        }
    }
    return array;
}

template <int D>
VtuArray exactVectors(const std::vector<Vec<D>>& values)
{
    VtuArray array{D, {}, false, {}, {}};
    array.values.reserve(D * values.size());
    for (const auto& v : values)
    {
        for (int d = 0; d < D; ++d)
        {
            array.values.push_back(v[d]);
        }
    }
    return array;
}

template <int D>
VtuArray exactMatrices(const std::vector<Mat<D>>& values)
{
    VtuArray array{D * D, {}, false, {}, {}};
    array.values.reserve(D * D * values.size());
    for (const auto& m : values)
    {
        for (int i = 0; i < D; ++i)
        {
            for (int j = 0; j < D; ++j)
            {
                array.values.push_back(m(i, j));
            }
        }
    }
    return array;
}

template <class T>
VtuArray scalars(const std::vector<T>& values, bool integer)
{
    VtuArray array{1, {}, integer, {}, {}};
    array.values.assign(values.begin(), values.end());
    return array;
}

VtuArray scalar(double value)
{
    return VtuArray{1, {value}, false, {}, {}};
}

const VtuArray& need(const VtuData& data, const std::map<std::string, VtuArray>& arrays,
                     const std::string& name, const std::string& file)
{
    (void)data;
    const auto found = arrays.find(name);
    if (found == arrays.end())
    {
        throw InputError("cannot restart from '" + file + "': it has no array '" + name + "'",
                         {"It was written by an older or different program; start afresh with "
                          "startFrom startTime."});
    }
    return found->second;
}

// Reads an array of `stride` components per particle (D for the restart arrays, 3 for points).
template <int D>
void readVectors(const std::vector<double>& values, std::size_t stride, std::vector<Vec<D>>& out)
{
    for (std::size_t a = 0; a < out.size(); ++a)
    {
        for (int d = 0; d < D; ++d)
        {
            out[a][d] = values[stride * a + static_cast<std::size_t>(d)];
        }
    }
}

template <int D>
void readMatrices(const VtuArray& array, std::vector<Mat<D>>& out)
{
    for (std::size_t a = 0; a < out.size(); ++a)
    {
        for (int i = 0; i < D; ++i)
        {
            for (int j = 0; j < D; ++j)
            {
                out[a](i, j) = array.values[static_cast<std::size_t>(D * D) * a +
                                            static_cast<std::size_t>(D * i + j)];
            }
        }
    }
}

} // namespace

template <int D>
void Simulation<D>::writeSummary(const RunSummary& summary, const std::string& failure) const
{
    boost::property_tree::ptree tree;
    tree.put("case", caseName_);
    tree.put("dimension", D);
    tree.put("particles", particles_.size());
    tree.put("spacing", spacing_);
    tree.put("kernel", kernel_->name());
    tree.put("hOverDx", kernel_->hOverDx());
    tree.put("formulation", formulation_->summary());
    tree.put("stabilisation", scheme_->summary());
    tree.put("contact", contact_->summary());
    tree.put("courant", control_.courant);
    tree.put("status", failure.empty() ? "finished" : "failed");
    tree.put("failure", failure);
    tree.put("endTime", control_.endTime);
    tree.put("time", time_);
    tree.put("steps", summary.steps);
    tree.put("threads", omp_get_max_threads());
    tree.put("wallSeconds", summary.wallSeconds);
    tree.put("particleStepsPerSecond", summary.particleStepsPerSecond);
    tree.put("outputSeconds", summary.outputSeconds);
    tree.put("computeParticleStepsPerSecond", summary.computeParticleStepsPerSecond);
    tree.put("peakMemoryMB", summary.peakMemoryMB);
    for (const auto& object : functionObjects_)
    {
        for (const auto& [key, value] : object->results())
        {
            tree.put(boost::property_tree::ptree::path_type("functions/" + object->name() + "/" + key, '/'),
                     value);
        }
    }
    std::ostringstream text;
    boost::property_tree::write_json(text, tree);
    writeTextAtomically(dicts_.caseDir() / "postProcessing" / "summary.json", text.str());
}

template <int D>
void Simulation<D>::removeOldOutput()
{
    const std::filesystem::path folder = dicts_.caseDir() / "VTK";
    if (std::filesystem::is_directory(folder))
    {
        for (const auto& file : std::filesystem::directory_iterator(folder))
        {
            if (outputIndexOf(file.path().filename().string(), caseName_) >= 0)
            {
                std::filesystem::remove(file.path());
            }
        }
    }
    std::error_code ec;
    std::filesystem::remove(pvd_.file(), ec);
    pvd_ = PvdSeries(pvd_.file());
}

template <int D>
void Simulation<D>::writeOutput(bool restartable, long step, double time,
                                const std::map<std::string, double>& functionState)
{
    const std::size_t n = particles_.size();
    VtuData data;
    data.points.reserve(3 * n);
    for (const auto& x : particles_.x)
    {
        for (int d = 0; d < 3; ++d)
        {
            data.points.push_back(d < D ? x[d] : 0.0);
        }
    }
    std::vector<Vec<D>> displacement(n);
    std::vector<double> J(n);
    for (std::size_t a = 0; a < n; ++a)
    {
        displacement[a] = particles_.x[a] - particles_.X[a];
        J[a] = particles_.F[a].determinant();
    }
    data.pointData["displacement"] = displayVectors<D>(displacement);
    data.pointData["velocity"] = displayVectors<D>(velocitySync_);
    data.pointData["F"] = displayMatrices<D>(particles_.F, true);
    data.pointData["P"] = displayMatrices<D>(particles_.P, false);
    VtuArray jacobian{1, {}, false, {}, {}};
    jacobian.singles.assign(J.begin(), J.end());
    data.pointData["J"] = jacobian;
    data.pointData["bodyId"] = scalars(particles_.body, true);
    data.pointData["fixed"] = scalars(particles_.fixed, true);
    // What a restart needs beyond the display fields.
    data.pointData["initialPosition"] = exactVectors<D>(particles_.X);
    data.pointData["initialVolume"] = scalars(particles_.V0, false);
    data.pointData["mass"] = scalars(particles_.m, false);
    data.pointData["velocityHalfStep"] = exactVectors<D>(particles_.v);
    const ReferenceConfiguration<D>& ref = reference_->reference();
    if (formulation_->updatesReference())
    {
        data.pointData["referencePosition"] = exactVectors<D>(ref.x);
        data.pointData["referenceVolume"] = scalars(ref.V, false);
        data.pointData["referenceF"] = exactMatrices<D>(ref.F);
        if (!ref.K.empty())
        {
            VtuArray K{D * D * D, {}, false, {}, {}};
            K.values.reserve(D * D * D * n);
            for (const auto& tensor : ref.K)
            {
                for (int i = 0; i < D; ++i)
                {
                    for (int j = 0; j < D; ++j)
                    {
                        for (int k = 0; k < D; ++k)
                        {
                            K.values.push_back(tensor(i, j, k));
                        }
                    }
                }
            }
            data.pointData["referenceK"] = K;
        }
    }
    data.fieldData["TimeValue"] = scalar(time);
    data.fieldData["step"] = scalar(static_cast<double>(step));
    data.fieldData["restartable"] = scalar(restartable ? 1.0 : 0.0);
    data.fieldData["deltaT"] = scalar(deltaT_);
    data.fieldData["previousDeltaT"] = scalar(previousDeltaT_);
    data.fieldData["firstDeltaT"] = scalar(firstDeltaT_);
    data.fieldData["halfStepVelocity"] = scalar(halfStepVelocity_ ? 1.0 : 0.0);
    data.fieldData["outputIndex"] = scalar(static_cast<double>(outputIndex_));
    data.fieldData["nextOutputTime"] = scalar(nextOutputTime_);
    data.fieldData["externalWork"] = scalar(externalWork_);
    data.fieldData["contactWork"] = scalar(contactWork_);
    data.fieldData["initialEnergy"] = scalar(initialEnergy_);
    data.fieldData["haveInitialEnergy"] = scalar(haveInitialEnergy_ ? 1.0 : 0.0);
    data.fieldData["referenceUpdateStep"] = scalar(static_cast<double>(ref.updateStep));
    data.fieldData["dimension"] = scalar(D);
    for (const auto& [key, value] : functionState)
    {
        data.fieldData[key] = scalar(value);
    }
    data.stringFields["bodyNames"] = bodyNames_;

    const std::string name = caseName_ + "_" + std::to_string(outputIndex_) + ".vtu";
    writeVtu(dicts_.caseDir() / "VTK" / name, data);
    pvd_.add(time, name);
    ++outputIndex_;
}

template <int D>
bool Simulation<D>::restoreLatest(RunLog& log)
{
    pvd_.load();
    const std::filesystem::path folder = dicts_.caseDir() / "VTK";
    for (auto entry = pvd_.entries().rbegin(); entry != pvd_.entries().rend(); ++entry)
    {
        const std::filesystem::path path = folder / entry->file;
        if (!std::filesystem::exists(path))
        {
            continue;
        }
        const VtuData data = readVtu(path);
        const auto& fields = data.fieldData;
        const auto restartable = fields.find("restartable");
        if (restartable == fields.end() || restartable->second.values.at(0) != 1.0)
        {
            continue;
        }
        const std::string file = path.string();
        const auto field = [&](const std::string& name) {
            return need(data, fields, name, file).values.at(0);
        };
        if (data.pointCount() != particles_.size() || static_cast<int>(field("dimension")) != D ||
            data.stringFields.count("bodyNames") == 0 ||
            data.stringFields.at("bodyNames") != bodyNames_)
        {
            throw InputError("cannot restart from '" + file + "': it holds " +
                                 std::to_string(data.pointCount()) +
                                 " particles of other bodies or dimension than the case now",
                             {"The case changed since that output; start afresh with startFrom "
                              "startTime (or run Allclean)."});
        }
        const auto array = [&](const std::string& name) -> const VtuArray& {
            return need(data, data.pointData, name, file);
        };
        const std::size_t n = particles_.size();
        readVectors<D>(data.points, 3, particles_.x);
        readVectors<D>(array("initialPosition").values, D, particles_.X);
        readVectors<D>(array("velocityHalfStep").values, D, particles_.v);
        for (std::size_t a = 0; a < n; ++a)
        {
            particles_.V0[a] = array("initialVolume").values[a];
            particles_.m[a] = array("mass").values[a];
            particles_.fixed[a] = static_cast<std::uint8_t>(array("fixed").values[a]);
        }
        if (formulation_->updatesReference())
        {
            ReferenceConfiguration<D> saved;
            saved.x.resize(n);
            saved.V.resize(n);
            saved.F.resize(n);
            readVectors<D>(array("referencePosition").values, D, saved.x);
            saved.V = array("referenceVolume").values;
            readMatrices<D>(array("referenceF"), saved.F);
            if (reference_->carriesK())
            {
                saved.K.assign(n, Tensor3<D>::zero());
                const auto& K = array("referenceK").values;
                for (std::size_t a = 0; a < n; ++a)
                {
                    for (int i = 0; i < D; ++i)
                    {
                        for (int j = 0; j < D; ++j)
                        {
                            for (int k = 0; k < D; ++k)
                            {
                                saved.K[a](i, j, k) =
                                    K[static_cast<std::size_t>(D * D * D) * a +
                                      static_cast<std::size_t>(D * D * i + D * j + k)];
                            }
                        }
                    }
                }
            }
            saved.updateStep = static_cast<long>(field("referenceUpdateStep"));
            const ForceStatus status = reference_->restore(particles_, std::move(saved));
            if (!status.ok())
            {
                throw InputError("cannot restart from '" + file + "': the saved reference "
                                 "configuration is singular at " +
                                     particleName(static_cast<std::size_t>(status.badParticle)));
            }
        }
        step_ = static_cast<long>(field("step"));
        time_ = field("TimeValue");
        deltaT_ = field("deltaT");
        previousDeltaT_ = field("previousDeltaT");
        firstDeltaT_ = field("firstDeltaT");
        halfStepVelocity_ = field("halfStepVelocity") != 0.0;
        outputIndex_ = static_cast<long>(field("outputIndex"));
        nextOutputTime_ = field("nextOutputTime");
        externalWork_ = field("externalWork");
        contactWork_ = field("contactWork");
        initialEnergy_ = field("initialEnergy");
        haveInitialEnergy_ = field("haveInitialEnergy") != 0.0;
        for (auto& object : functionObjects_)
        {
            const std::string prefix = "fo:" + object->name() + ":";
            std::map<std::string, double> own;
            for (const auto& [key, value] : fields)
            {
                if (key.rfind(prefix, 0) == 0)
                {
                    own[key.substr(prefix.size())] = value.values.at(0);
                }
            }
            if (!own.empty())
            {
                object->restoreState(own);
            }
        }
        // This level is computed and written again; later outputs are stale.
        pvd_.keepBefore(time_);
        pvd_.write();
        for (const auto& other : std::filesystem::directory_iterator(folder))
        {
            if (outputIndexOf(other.path().filename().string(), caseName_) > outputIndex_)
            {
                std::filesystem::remove(other.path());
            }
        }
        log.line("Restart     from " + path.filename().string() + " at step " +
                 std::to_string(step_) + ", t = " + std::to_string(time_) + " s");
        return true;
    }
    log.line("Restart     no restartable output in VTK/; starting from the initial state");
    return false;
}

template class Simulation<1>;
template class Simulation<2>;
template class Simulation<3>;

} // namespace sph
