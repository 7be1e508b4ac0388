// The forces of a level (Simulation.hpp): the internal forces with F and P, the close-pair
// energy's, the walls' and the artificial viscosity's, as accelerations.
#include "solver/Simulation.hpp"

#include "particles/Parallel.hpp"

namespace sph
{

// What the scheme reads at x^n with the reference as it is (atReference: x is the reference).
template <int D>
ForceInput<D> Simulation<D>::forceInput(bool atReference)
{
    ForceInput<D> in{particles_.x, particles_.V0, particles_.body, particles_.bodies,
                     materials_, reference_->reference(), atReference};
    in.owned = distributed() ? &owned_ : nullptr;
    in.globalId = distributed() ? &globalId_ : nullptr;
    return in;
}

// F, P and T at x^n, into spare buffers first: a failed evaluation leaves the last good F, P.
template <int D>
ForceStatus Simulation<D>::computeForces(bool atReference, bool wantEnergy)
{
    const ForceInput<D> in = forceInput(atReference);
    ForceStatus status = internalForces(in, acceleration_, wantEnergy);
    checkStatus(status, "computing the internal forces");
    particles_.F.swap(nextF_);
    particles_.P.swap(nextP_);
    if (distributed())
    {
        // The time step reads F: the owners' values, not those of ghosts cut at the layer's edge.
        refreshGhosts({"deformationGradient", "firstPiolaKirchhoffStress"});
        if (wantEnergy)
        {
            status.strainEnergy = comm_.sum(status.strainEnergy);
        }
    }
    return status;
}

// The internal forces: the scheme's and the close-pair energy's (F and P in nextF_, nextP_).
template <int D>
ForceStatus Simulation<D>::internalForces(const ForceInput<D>& in, std::vector<Vec<D>>& T,
                                          bool wantEnergy)
{
    ForceOutput<D> out{T, nextF_, nextP_};
    ForceStatus status = scheme_->computeForces(in, out, wantEnergy);
    if (status.ok() && impenetrability_)
    {
        status.strainEnergy +=
            impenetrability_->addForces(in.x, in.V0, in.body, in.ref, in.owned, T, wantEnergy);
    }
    return status;
}

// a = T/m + g in place of the forces; fixed particles discard theirs.
template <int D>
void Simulation<D>::accelerate()
{
    const std::size_t n = particles_.size();
#pragma omp parallel for schedule(static) if (useThreads(n))
    for (std::size_t a = 0; a < n; ++a)
    {
        acceleration_[a] = particles_.fixed[a]
                               ? Vec<D>::Zero()
                               : Vec<D>(acceleration_[a] / particles_.m[a] + gravity_);
    }
}

// The walls act as forces at x^n, t^n (walls/WallSet.hpp), so the leapfrog integrates them like
// the internal forces; the friction work of the last drift is completed with F_t^n.
template <int D>
void Simulation<D>::applyWalls(double dt)
{
    if (walls_->empty())
    {
        return;
    }
    walls_->applyForces(particles_, particles_.v, time_, dt, acceleration_);
    audit_.addWallWork(walls_->completeFrictionWork(particles_.x, previousX_));
}

// The viscosity reads v^{n-1/2}, so it is known before Δt_n, which it bounds
// (artificialViscosity/monaghan/Monaghan.cpp).
template <int D>
void Simulation<D>::computeViscosity()
{
    if (viscosity_->active())
    {
        viscosity_->compute({particles_.x, particles_.v, particles_, distributed() ? &ranks_ : nullptr},
                            viscousAcceleration_);
    }
}

template <int D>
void Simulation<D>::applyViscosity()
{
    if (!viscosity_->active())
    {
        return;
    }
    const std::size_t n = particles_.size();
#pragma omp parallel for schedule(static) if (useThreads(n))
    for (std::size_t a = 0; a < n; ++a)
    {
        acceleration_[a] += viscousAcceleration_[a]; // zero for fixed particles
    }
    audit_.completeViscousWork(particles_.m, viscousAcceleration_, particles_.x, previousX_);
}

template class Simulation<1>;
template class Simulation<2>;
template class Simulation<3>;

} // namespace sph
