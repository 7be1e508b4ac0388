// The motion of a step (Simulation.hpp): the drift and its work, the contact kick, kinetic
// damping, and the particles' order along a bar.
#include "solver/Simulation.hpp"

namespace sph
{

template <int D>
void Simulation<D>::drift(double dt)
{
    previousX_ = particles_.x;
    integrator_->advance(dt, acceleration_, particles_.fixed, particles_.x);
    if (!gravity_.isZero())
    {
        audit_.addGravityWork(particles_.m, gravity_, particles_.x, previousX_);
    }
    if (!walls_->empty())
    {
        audit_.addWallWork(walls_->driftWork(particles_, previousX_, time_, dt));
    }
    if (viscosity_->active())
    {
        audit_.addViscousDrift(particles_.m, viscousAcceleration_, particles_.x, previousX_);
    }
}

// Contact acts on v^{n+1/2} at x^{n+1} with the volumes there (spec §9, §12): F at x^{n+1}
// from the scheme, for the particles the contact model asks about.
template <int D>
void Simulation<D>::applyContact(double dt)
{
    if (!contact_->active())
    {
        return;
    }
    ContactState<D> state{particles_.x, particles_.v, particles_, dt, [this](std::size_t a) {
                              return scheme_->deformationGradient(a, particles_.x,
                                                                  reference_->reference())
                                  .determinant();
                          }};
    state.ranks = distributed() ? &ranks_ : nullptr;
    contact_->apply(state, contactDeltaV_);
    audit_.addContactKick(particles_.m, contactDeltaV_, particles_.v, dt);
}

// Kinetic damping (docs/theory/geotechnics.md §E2) on the final v^{n+1/2}, after the contact
// kick: at a peak of K the particles are at rest at x^{n+1}; the ghosts' copies are refreshed
// after it.
template <int D>
void Simulation<D>::dampKinetic(double dt)
{
    if (damping_ &&
        damping_->peakPassed(audit_.kineticEnergy(particles_.m, particles_.v), particles_.v,
                             dampingDeltaV_))
    {
        integrator_->restAtLevel();
        audit_.addDampingReset(dt);
    }
}

// Particles must not pass each other along a bar (1D; every rank of a distributed run learns
// of a crossing on any of them and stops alike).
template <int D>
void Simulation<D>::checkOrder(double dt)
{
    if constexpr (D == 1)
    {
        const long crossed = crossingParticle();
        const bool anywhere =
            distributed() ? comm_.maximum(crossed >= 0 ? 1.0 : 0.0) > 0.0 : crossed >= 0;
        if (anywhere)
        {
            time_ += dt;
            ++step_;
            fail(crossed >= 0 ? ForceStatus::failed(FailureKind::particleCrossing, crossed, 0.0,
                                                    "particle order (it passed its neighbour)")
                              : ForceStatus{},
                 "after moving the particles");
        }
    }
    (void)dt;
}

template class Simulation<1>;
template class Simulation<2>;
template class Simulation<3>;

} // namespace sph
