#pragma once
// Kinetic damping (dynamic relaxation; docs/theory/geotechnics.md §E2): a run that is asked for
// a static state, not for a motion, follows its undamped leapfrog until the kinetic energy of
// the half steps, K^{n+1/2} = Σ ½ m |v^{n+1/2}|², falls below that of the step before. The
// energy passed a peak there, where the potential energy is lowest along the path; every
// velocity is set to zero and the motion starts again from rest. Each reset removes about
// K^{n+1/2}, which the energy audit books as `damped` (EnergyAudit::addDampingKick); a state that
// cannot come to rest (a slope that fails) keeps gaining kinetic energy between resets.
//
// No parameter: the peak is detected, not tuned. The test is strict (<), so a state at rest
// (K = 0 at every step) is not reset again.

#include "core/RunScalars.hpp"
#include "particles/Types.hpp"

#include <vector>

namespace sph
{

template <int D> class KineticDamping
{
public:
    void declareState(RunScalars& scalars)
    {
        scalars.bind("kineticDampingLastEnergy", last_);
        scalars.bind("kineticDampingResets", resets_);
    }

    // After the step's kick and drift: `kinetic` = K^{n+1/2} of `velocity` (summed over every
    // rank). At a peak every velocity is set to zero and `deltaV` holds the change, -v^{n+1/2}
    // (for the energy audit); returns whether it reset.
    bool afterStep(double kinetic, std::vector<Vec<D>>& velocity, std::vector<Vec<D>>& deltaV)
    {
        if (!(kinetic < last_))
        {
            last_ = kinetic;
            return false;
        }
        for (std::size_t a = 0; a < velocity.size(); ++a)
        {
            deltaV[a] = -velocity[a];
            velocity[a].setZero();
        }
        last_ = 0.0;
        ++resets_;
        return true;
    }

    long resets() const { return resets_; }

private:
    double last_ = 0.0; // K^{n-1/2} (0 after a reset)
    long resets_ = 0;
};

} // namespace sph
