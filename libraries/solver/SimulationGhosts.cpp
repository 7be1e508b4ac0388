// The ghost layer of a distributed run (docs/parallel.md): how far it reaches, in the reference
// configuration and, for contact and the viscosity, in the current one; when it is gathered
// again as particles move (and the particles partitioned again); what a rank rebuilds for a new
// set of local particles; which of the ghosts' fields are refreshed from their owners, when.
// The rest of a distributed run (partition, reductions the models see, failures, output) is in
// SimulationDistributed.cpp.
#include "solver/Simulation.hpp"

#include "parallel/RcbPartition.hpp"

#include <algorithm>

namespace sph
{

// Ghosts are needed as far as an owned particle's force reaches: the force on c gathers what its
// neighbours a computed (their F, P, corrected gradients, gradF's samples), and each of those
// reads a's own neighbours' positions: two search radii in the reference configuration (the
// bit-identity tests fail with one). Plus a skin, so that an updated-Lagrangian reference can
// move several times before the ghosts must be gathered again (regatherDue).
template <int D>
double Simulation<D>::ghostWidth() const
{
    return 2.0 * scheme_->referenceNeeds(*kernel_).searchRadius + ghostSkin();
}

template <int D>
double Simulation<D>::ghostSkin() const
{
    return 0.5 * scheme_->referenceNeeds(*kernel_).searchRadius;
}

// How far, in the current configuration, the models read other particles' state: contact two
// of its reaches (a's kick reads its neighbours b, and the R_b each of those computed from its
// own), the artificial viscosity one (v, x and F of its neighbours). 0: nothing reads x^n.
template <int D>
double Simulation<D>::currentReach() const
{
    double reach = 0.0;
    if (contact_->active())
    {
        reach = std::max(reach, 2.0 * contact_->reach());
    }
    if (viscosity_->active())
    {
        reach = std::max(reach, viscosity_->reach());
    }
    return reach;
}

// The ghosts in x reach currentReach() plus a skin of half a model's reach, so that particles
// can move several steps before they are gathered again.
template <int D>
double Simulation<D>::currentSkin() const
{
    return 0.5 * std::max(contact_->active() ? contact_->reach() : 0.0,
                          viscosity_->active() ? viscosity_->reach() : 0.0);
}

// While no particle's x^r has moved more than half the skin since the ghosts were gathered,
// every particle within two radii of an owned one is still among them: the owned particles and
// the one that would be missing have each moved less than half the skin. The maximum is over
// the owned particles of every rank, so it covers every particle.
template <int D>
bool Simulation<D>::regatherDue() const
{
    return movedFarther(reference_->reference().x, gatheredAt_, 0.5 * ghostSkin());
}

// The same for the ghosts in x (contact, viscosity): checked after each drift (particles move
// every step; the reference only at its moves).
template <int D>
bool Simulation<D>::currentRegatherDue() const
{
    return currentReach() > 0.0 && movedFarther(particles_.x, gatheredX_, 0.5 * currentSkin());
}

// Whether some owned particle, on any rank, is farther than `distance` from where it was.
template <int D>
bool Simulation<D>::movedFarther(const std::vector<Vec<D>>& now, const std::vector<Vec<D>>& then,
                                 double distance) const
{
    double moved2 = 0.0;
    for (std::size_t a = 0; a < now.size(); ++a)
    {
        if (owned_[a])
        {
            moved2 = std::max(moved2, (now[a] - then[a]).squaredNorm());
        }
    }
    return comm_.maximum(moved2) > distance * distance;
}

// The ghosts are chosen in the reference configuration, where the neighbour lists are built:
// X for a total-Lagrangian run, x^r for an updated-Lagrangian one (called after a move); with
// contact, also in the current configuration x (called after a drift). A contact ghost may lie
// far from the rank's particles in the reference configuration, where its neighbourhood is cut:
// what the rank computes for it there is wrong and read by nothing (its failures do not count,
// its F and P are its owner's after the forces, its J comes from its owner).
//
// Before, the particles are partitioned again (RCB at these positions) when the ranks' loads
// have drifted apart by more than maxLoadImbalance (controlDict): a rank computes its owned
// particles and its ghosts, and a body that moves stretches its ranks' regions, and with them
// their ghost layers. Every rank takes the same decision (a maximum and a sum in rank order).
template <int D>
void Simulation<D>::regather()
{
    const std::vector<Vec<D>>& positions =
        formulation_->updatesReference() ? reference_->reference().x : particles_.X;
    const auto load = static_cast<double>(particles_.size());
    const bool started = comm_.maximum(static_cast<double>(exchange_->ghostCount())) > 0.0;
    const double mean = comm_.sum(load) / comm_.size();
    if (started && comm_.maximum(load) > control_.maxLoadImbalance * mean)
    {
        exchange_->removeGhosts(fields_);
        const std::vector<std::uint64_t> ids(globalId_.begin(), globalId_.end());
        exchange_->migrate(fields_, globalId_, rcbOwners<D>(comm_, positions, ids));
        ++repartitions_;
    }
    std::vector<typename ParticleExchange<D>::GhostReach> reaches{{&positions, ghostWidth()}};
    if (currentReach() > 0.0)
    {
        reaches.push_back({&particles_.x, currentReach() + currentSkin()});
    }
    exchange_->addGhosts(fields_, reaches, globalId_);
    localParticlesChanged();
    gatheredAt_ = positions;
    gatheredX_ = particles_.x;
    ++gathers_;
}

template <int D>
void Simulation<D>::localParticlesChanged()
{
    owned_ = exchange_->ownedMask(particles_.size());
    reference_->reference().owned = &owned_;
    // Global indices number the bodies one after another, so each body is a contiguous range
    // of the local particles too.
    for (std::size_t b = 0; b < particles_.bodies.size(); ++b)
    {
        const auto [first, last] =
            std::equal_range(particles_.body.begin(), particles_.body.end(), static_cast<int>(b));
        particles_.bodies[b].begin = static_cast<std::size_t>(first - particles_.body.begin());
        particles_.bodies[b].end = static_cast<std::size_t>(last - particles_.body.begin());
    }
    reference_->reference().candidates.clear(); // the last search's indices are stale
    viscosity_->particlesChanged();
    checkCrossingOrder(); // 1D: the bars' order of the new local particles
    const ForceStatus status = formulation_->updatesReference()
                                   ? reference_->restored(particles_)
                                   : reference_->initialise(particles_);
    // Only owned particles are checked (a ghost's neighbourhood may be cut where the rank's
    // particles end), and theirs are whole: the serial run's. The first time, that is the
    // setup's check (the whole set's neighbourhoods were never built on one rank): the serial
    // run's input error, worded by the owner of the failing particle with the least global
    // index, thrown by every rank alike (and so reported once).
    if (!neighbourhoodsChecked_)
    {
        neighbourhoodsChecked_ = true;
        const bool singular = !status.ok() && status.failure == FailureKind::singularReference;
        const int root = wordingRank(singular ? status.badParticle : -1);
        if (root >= 0)
        {
            const bool here = comm_.rank() == root;
            const std::string particle = comm_.broadcast(
                here ? particleName(static_cast<std::size_t>(status.badParticle)) : "", root);
            throw tooFewNeighbours(particle, comm_.broadcast(here ? status.message : "", root));
        }
    }
    checkStatus(status, "rebuilding the reference configuration of a rank's particles");
}

template <int D>
void Simulation<D>::refreshGhosts(const std::vector<std::string>& names)
{
    if (distributed())
    {
        exchange_->updateGhosts(fields_, names);
    }
}

// The fields a move of the reference changes: the reference's own, and the materials' history
// where the scheme rebases it (gradF elasticState, docs/theory/gradF-plastic.md §G4).
template <int D>
std::vector<std::string> Simulation<D>::fieldsAMoveChanges() const
{
    std::vector<std::string> names = reference_->fieldNames();
    for (const auto& material : materialModels_)
    {
        for (const std::string& name :
             scheme_->movesParticleHistory() ? material->rebasedFields() : std::vector<std::string>{})
        {
            if (std::find(names.begin(), names.end(), name) == names.end())
            {
                names.push_back(name);
            }
        }
    }
    return names;
}

// What an owned particle reads of a ghost is its position, its reference (x^r, V^r, F^r, K:
// refreshed at each move) and what never changes (V0, body). The rest of a ghost is recomputed
// before anything reads it (F and P, refreshed after the forces), or read by nothing (its
// velocity, until the next gather sends every field).
template <int D>
void Simulation<D>::refreshGhostPositions()
{
    refreshGhosts({positionField});
}

// After the drift: the ghosts in x are gathered again when particles have moved half their
// skin (contact, viscosity).
template <int D>
void Simulation<D>::followMovingParticles()
{
    if (distributed() && currentRegatherDue())
    {
        regather();
    }
}

// The viscosity reads its neighbours' v^{n-1/2}: the owners' (a ghost's own drifted with forces
// cut at the edge of the layer, and missed its contact kick).
template <int D>
void Simulation<D>::refreshGhostVelocities()
{
    if (viscosity_->active())
    {
        refreshGhosts({integrator_->velocityField()});
    }
}

template class Simulation<1>;
template class Simulation<2>;
template class Simulation<3>;

} // namespace sph
