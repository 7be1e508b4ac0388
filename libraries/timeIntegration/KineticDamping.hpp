#pragma once
// Kinetic damping (dynamic relaxation; docs/theory/geotechnics.md §E2): a run that is asked for
// a static state, not for a motion, follows its undamped leapfrog until the kinetic energy of
// the half steps, K^{n+1/2} = Σ ½ m |v^{n+1/2}|², falls below that of the step before. The
// energy passed a peak there, where the potential energy is lowest along the path; the
// particles are put at rest at the level x^{n+1} (TimeIntegration::restAtLevel: v^{n+1} = 0,
// and the leapfrog starts again as from t = 0). The energy audit books what that removes,
// Σ ½ m |v^{n+1/2} + ½Δt a^{n+1}|² (the level's kinetic energy the undamped step would have had),
// as `damped`; a state that cannot come to rest (a slope that fails) keeps moving.
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
    // rank). Returns whether the energy passed a peak: then `removed` holds v^{n+1/2} (for the
    // energy audit) and the caller puts the particles at rest.
    bool peakPassed(double kinetic, const std::vector<Vec<D>>& velocity,
                    std::vector<Vec<D>>& removed)
    {
        if (!(kinetic < last_))
        {
            last_ = kinetic;
            return false;
        }
        removed = velocity;
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
