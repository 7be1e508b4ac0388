// The moves of the reference configuration within the time loop (Simulation.hpp): when it
// moves, Π before the move for the energy audit (§G6), the kick split at a move (the closing
// forces of the reference before it, docs/theory/gradF-plastic.md §G20) and the strain since
// the last move (referenceUpdateStrain, §G21).
#include "solver/Simulation.hpp"

#include "particles/Parallel.hpp"

namespace sph
{

// The reference's part of a level, before its forces: this level's strain decision, the split
// kick's closing forces, the move. x is the reference configuration bitwise (f = I exactly)
// when the reference was just moved
// here, or, at the first level of a run (fresh or restarted), if the arrays say so (an
// initial displacement makes x differ from X = x^r).
template <int D>
bool Simulation<D>::moveReference(long firstStep)
{
    if (step_ != firstStep)
    {
        reference_->beginLevel();
    }
    // The kick split at a move: the closing forces with the reference before it (§G20).
    kickSplitHere_ = splitKick_ && step_ != firstStep && reference_->moveDue(step_);
    if (kickSplitHere_)
    {
        computeClosingForces();
    }
    ForceStatus status;
    // Distributed: every rank learns of a failure at the move before going on, and the ghosts'
    // new reference is their owners' (an outer ghost's own is cut at the layer's edge) before
    // the corrected gradients are built from it.
    const typename ReferenceManager<D>::MoveHooks hooks{
        [this](const ForceStatus& moveStatus) {
            checkStatus(moveStatus, "moving the reference configuration");
        },
        [this] { refreshGhosts(fieldsAMoveChanges()); }};
    // Π at these positions with the reference before the move, against Π with the moved one
    // from the force evaluation that follows (§G6).
    const std::optional<double> before =
        moveEnergyWanted_ && reference_->moveDue(step_) ? std::optional<double>(strainEnergyNow())
                                                        : std::nullopt;
    const bool moved = distributed() ? reference_->updateIfDue(step_, particles_, status, hooks)
                                     : reference_->updateIfDue(step_, particles_, status);
    checkStatus(status, "moving the reference configuration");
    if (moved)
    {
        // What the move dissipated (gradF's openedSamples particle, gradF-plastic.md (G22.2))
        // is booked as such, and the move's change of Π is measured net of it (the reduction
        // only where the scheme can dissipate at a move).
        double dissipated = 0.0;
        if (scheme_->movesDissipate())
        {
            const double local = scheme_->moveDissipation(distributed() ? &owned_ : nullptr);
            dissipated = distributed() ? comm_.sum(local) : local;
            audit_.addDissipation(dissipated);
        }
        energyBeforeMove_ = before ? std::optional<double>(*before - dissipated) : std::nullopt;
    }
    if (moved && distributed() && regatherDue())
    {
        regather();
    }
    const ReferenceConfiguration<D>& ref = reference_->reference();
    return moved || (step_ == firstStep && ref.updateStep == step_ && ref.x == particles_.x);
}

template <int D>
double Simulation<D>::strainEnergyNow()
{
    const ForceInput<D> in = forceInput(false);
    double energy = scheme_->energy(in);
    if (impenetrability_)
    {
        energy += impenetrability_->energy(in.x, in.V0, in.body, in.ref, in.owned);
    }
    return distributed() ? comm_.sum(energy) : energy;
}

// The forces at x^n of the reference the step that ends here began with (before the move):
// the step closes with them (gradF-plastic.md §G20). F and P stay the last level's.
template <int D>
void Simulation<D>::computeClosingForces()
{
    closingForce_.resize(particles_.size());
    checkStatus(internalForces(forceInput(false), closingForce_, false),
                "computing the forces of the reference before its move (splitKick)");
}

// After the level's own forces T (the moved reference's, in acceleration_), T_close - T for the
// owned particles (a ghost's velocity is its owner's: no closing of its own).
template <int D>
void Simulation<D>::keepClosingDifference()
{
    const std::size_t n = particles_.size();
#pragma omp parallel for schedule(static) if (useThreads(n))
    for (std::size_t a = 0; a < n; ++a)
    {
        const bool own = !distributed() || owned_[a];
        closingForce_[a] = own ? Vec<D>(closingForce_[a] - acceleration_[a]) : Vec<D>::Zero();
    }
}

// a^n_close = a^n + (T_close - T)/m: gravity, walls, viscosity and contact do not depend on
// the reference, so the two accelerations differ by the internal forces alone.
template <int D>
const std::vector<Vec<D>>& Simulation<D>::closingAcceleration()
{
    const std::size_t n = particles_.size();
    closingAcceleration_.resize(n);
#pragma omp parallel for schedule(static) if (useThreads(n))
    for (std::size_t a = 0; a < n; ++a)
    {
        closingAcceleration_[a] = particles_.fixed[a]
                                      ? Vec<D>::Zero()
                                      : Vec<D>(acceleration_[a] + closingForce_[a] / particles_.m[a]);
    }
    return closingAcceleration_;
}

// After the level's own forces: the strain since the last move (a formulation that moves by
// strain reads it at the next level) and, where the kick is split, T_close - T.
template <int D>
void Simulation<D>::afterLevelForces()
{
    reference_->measureStrain(particles_.F, distributed() ? &owned_ : nullptr,
                              [this](double local) {
                                  return distributed() ? comm_.maximum(local) : local;
                              });
    if (kickSplitHere_)
    {
        keepClosingDifference();
    }
}

template class Simulation<1>;
template class Simulation<2>;
template class Simulation<3>;

} // namespace sph
