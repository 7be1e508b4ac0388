// A run on several ranks (mpirun -np N sphSolid -parallel; docs/parallel.md).
//
// Every rank builds the case whole, as a serial run does (models, bodies, initial conditions,
// the checks of the initial configuration), then keeps its share: RCB gives each rank a compact
// region, and around its owned particles each rank holds ghosts, copies of the particles of
// other ranks within ghostWidth(). The local particles, owned and ghosts, are kept in increasing
// global index (parallel/ParticleExchange.hpp), so every neighbour sum adds the serial run's
// terms in the serial order: positions, velocities and F are bit-identical to the serial run.
//
// Ghosts are computed like owned particles (their forces, F, the drift), which is exact for
// those whose neighbourhood is complete; the outer ones are not, so the owners' values replace
// them: F and P after each force evaluation (the time step reads them), positions after each
// drift (velocities too with the viscosity), every stored field at each gathering
// (SimulationGhosts.cpp). What decides the run is agreed by every rank: the time step is a
// maximum over the ranks, and a failure is the one at the least global index of any rank,
// diagnosed by its owner and stopping every rank alike.
#include "solver/Simulation.hpp"

#include "core/Application.hpp"
#include "core/InputError.hpp"
#include "core/IoError.hpp"
#include "io/PvtuFile.hpp"
#include "io/VtuFile.hpp"
#include "parallel/RcbPartition.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace sph
{

template <int D>
void Simulation<D>::checkDistributable() const
{
    const auto refuse = [](const std::string& what, const std::string& how) {
        throw InputError(what + " does not run on several ranks yet",
                         {how + "; or run this case serially (or on one rank). A distributed run "
                                "(sphSolid -parallel on more than one rank) supports 1D, 2D and "
                                "3D cases with any kernel, formulation and stabilisation, elastic "
                                "and plastic materials, contact between bodies, rigid walls, "
                                "artificial viscosity, gravity, fixed particles and the function "
                                "objects of sphSolid (docs/parallel.md)."});
    };
    if (viscosity_->active() && integrator_->velocityField().empty())
    {
        refuse("artificial viscosity with a time integration that names no velocity field",
               "A time integration names the field the viscosity reads "
               "(TimeIntegration::velocityField), so that ghosts get their owners' velocities");
    }
    for (const auto& object : functionObjects_)
    {
        if (!object->distributable())
        {
            refuse("function object '" + object->name() + "' (" + object->summary() + ")",
                   "A function object runs distributed when it visits the particles each rank "
                   "owns (StepState::rankView), combines the ranks' results ("
                   "particles/ParticleRanks.hpp) and says so (distributable())");
        }
    }
}

template <int D>
long Simulation<D>::globalIndex(std::size_t a) const
{
    return distributed() ? globalId_[a] : static_cast<long>(a);
}

template <int D>
void Simulation<D>::checkSetup()
{
    if (comm_.parallel() && !distributed())
    {
        distribute();
    }
}

template <int D>
void Simulation<D>::distribute()
{
    checkDistributable();
    globalCount_ = particles_.size();
    exchange_ = std::make_unique<ParticleExchange<D>>(comm_);
    shareRanks();
    audit_.countOwned(&owned_, [this](double local) { return comm_.sum(local); });
    // Every rank holds the whole set: each keeps an equal share, then RCB makes the shares
    // compact regions (the same partition on every run with the same ranks).
    const auto ranks = static_cast<std::size_t>(comm_.size());
    const auto rank = static_cast<std::size_t>(comm_.rank());
    std::vector<std::uint8_t> share(globalCount_, 0);
    std::fill(share.begin() + static_cast<long>(globalCount_ * rank / ranks),
              share.begin() + static_cast<long>(globalCount_ * (rank + 1) / ranks), 1);
    exchange_->keepOnly(fields_, share);
    const std::vector<std::uint64_t> ids(globalId_.begin(), globalId_.end());
    exchange_->migrate(fields_, globalId_, rcbOwners<D>(comm_, particles_.x, ids));
    regather();
}

// What the models see of the ranks (particles/ParticleRanks.hpp): the function objects visit
// the owned particles and reduce over the ranks, rank 0 writing postProcessing/; contact agrees
// on the bodies' boxes and takes the ghosts' current volumes from their owners.
template <int D>
void Simulation<D>::shareRanks()
{
    ranks_.owned = &owned_;
    ranks_.globalId = &globalId_;
    ranks_.writer = comm_.rank() == 0;
    ranks_.minimumOverRanks = [this](std::vector<double>& values) { comm_.minimum(values); };
    ranks_.maximumOverRanks = [this](std::vector<double>& values) { comm_.maximum(values); };
    ranks_.sumOverRanks = [this](std::vector<double>& values) { comm_.sum(values); };
    walls_->setRanks(&ranks_);
    ranks_.ownersToGhosts = [this](std::vector<double>& values) {
        exchange_->updateGhostValues(values);
    };
    ranks_.gatherOnWriter = [this](const std::vector<double>& values) {
        std::vector<std::vector<double>> toEach(static_cast<std::size_t>(comm_.size()));
        toEach[0] = values;
        std::vector<double> joined;
        for (const std::vector<double>& from : comm_.exchange(toEach))
        {
            joined.insert(joined.end(), from.begin(), from.end());
        }
        return joined;
    };
}

// The log's account of the distribution: repartitions, ghosts and traffic per rank.
template <int D>
std::string Simulation<D>::distributionReport(long steps) const
{
    const double ranks = comm_.size();
    const double ghosts = comm_.sum(static_cast<double>(exchange_->ghostCount())) / ranks;
    const double bytes = comm_.sum(static_cast<double>(exchange_->totalBytesSent())) / ranks;
    std::ostringstream out;
    out << "Ranks       " << comm_.size() << ": " << gathers_ << " ghost gathers, " << repartitions_
        << " repartitions; per rank, " << std::lround(ghosts) << " ghosts ("
        << std::lround(100.0 * ghosts / (static_cast<double>(globalCount_) / ranks))
        << " % of its owned particles) and " << std::lround(bytes / std::max(1L, steps) / 1024.0)
        << " kB sent per step (means at the end)";
    return out.str();
}

// Serially: fails when the status does. Distributed: every rank learns whether any failed,
// and the owner of the failing particle with the least global index words the diagnosis.
template <int D>
void Simulation<D>::checkStatus(const ForceStatus& status, const std::string& when)
{
    if (!distributed())
    {
        if (!status.ok())
        {
            failWith(describeFailure(status, when));
        }
        return;
    }
    const int root = wordingRank(!status.ok() ? status.badParticle : -1);
    if (root < 0)
    {
        return;
    }
    const std::string diagnosis =
        comm_.broadcast(comm_.rank() == root ? describeFailure(status, when) : "", root);
    failWith(diagnosis);
}

template <int D>
int Simulation<D>::wordingRank(long badParticle) const
{
    constexpr double none = std::numeric_limits<double>::infinity();
    const double mine =
        badParticle < 0 ? none : static_cast<double>(globalIndex(static_cast<std::size_t>(badParticle)));
    const double first = comm_.minimum(mine);
    if (first == none)
    {
        return -1;
    }
    return static_cast<int>(comm_.minimum(mine == first ? comm_.rank() : none));
}

// Each rank writes its owned particles as VTK/<case>_<n>/<case>_<n>_<rank>.vtu; rank 0 writes
// VTK/<case>_<n>.pvtu, which names them, and adds it to the series. A failed write on any rank
// stops every rank with that rank's I/O error (nothing damaged replaces a good file).
template <int D>
void Simulation<D>::writePieces(const VtuData& header, const std::vector<std::size_t>& ownedParticles,
                                double time)
{
    const std::string stem = caseName_ + "_" + std::to_string(outputIndex_);
    const std::filesystem::path folder = dicts_.caseDir() / "VTK";
    std::vector<std::string> pieces;
    for (int r = 0; r < comm_.size(); ++r)
    {
        pieces.push_back(stem + "/" + stem + "_" + std::to_string(r) + ".vtu");
    }
    const VtuPieceFill fill = [&](std::size_t begin, std::size_t end, VtuData& piece) {
        writeStatePoints<D>(fields_, &ownedParticles, begin, end, piece);
    };
    std::string error;
    try
    {
        if (comm_.rank() == 0)
        {
            std::filesystem::create_directories(folder / stem);
        }
        comm_.barrier();
        writeVtuInPieces(folder / pieces[static_cast<std::size_t>(comm_.rank())], header,
                         ownedParticles.size(), fill);
    }
    catch (const IoError& failure)
    {
        error = failure.what();
    }
    catch (const std::filesystem::filesystem_error& failure)
    {
        error = failure.what();
    }
    const auto failed = static_cast<int>(comm_.minimum(error.empty() ? comm_.size() : comm_.rank()));
    if (failed < comm_.size())
    {
        throw IoError(comm_.broadcast(error, failed));
    }
    if (comm_.rank() == 0)
    {
        VtuData layout = header; // the arrays' names, types and components (no points)
        fill(0, 0, layout);
        writePvtu(folder / (stem + ".pvtu"), layout, pieces);
        pvd_.add(time, stem + ".pvtu");
        // An output written again after a restart on fewer ranks: the surplus pieces go.
        std::vector<std::filesystem::path> surplus;
        for (const auto& file : std::filesystem::directory_iterator(folder / stem))
        {
            const std::string relative = stem + "/" + file.path().filename().string();
            if (std::find(pieces.begin(), pieces.end(), relative) == pieces.end())
            {
                surplus.push_back(file.path());
            }
        }
        for (const auto& file : surplus)
        {
            std::error_code ec;
            std::filesystem::remove(file, ec);
        }
    }
    lastOutputFile_ = stem + ".pvtu";
}

template class Simulation<1>;
template class Simulation<2>;
template class Simulation<3>;

} // namespace sph
