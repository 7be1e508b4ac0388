#pragma once
// Time integration (system/sphSchemes), runtime-selectable:
//
//   timeIntegration { type leapfrog; }     // optional; leapfrog is the default
//
// A time integrator owns the particle velocity it advances (v^{n±½} for the leapfrog), the
// time step Δt with its control (α h / max c from controlDict's `courant`, recomputed every
// `timeStepUpdateInterval` steps) and the collapse check, and declares all of that state in
// the registries so output and restart need not know it.

#include "core/Registry.hpp"
#include "core/RunScalars.hpp"
#include "particles/ParticleFields.hpp"
#include "stabilisation/Stabilisation.hpp"

#include <functional>
#include <string>
#include <vector>

namespace sph
{

// What bounds the time step (spec §10): the smoothing length and the largest wave speed of the
// current state (computed only when the step is due), and, to diagnose a collapse only, the
// particle where the wave speed is largest.
struct WaveSpeedBound
{
    double h = 0.0;
    std::function<double()> maxWaveSpeed;
    std::function<std::size_t()> fastestParticle;
};

template <int D>
class TimeIntegration : public RegisteredModel
{
public:
    static constexpr const char* family = "timeIntegration";
    static constexpr int dimension = D;
    struct Args
    {
        double courant = 0.0;             // α in Δt = α h / c
        long timeStepUpdateInterval = 1;  // recompute Δt every N steps (0: only at the start)
    };

    virtual ~TimeIntegration() = default;

    // The velocity array it advances (the particles' own) and its state in the registries.
    virtual void attach(std::vector<Vec<D>>& velocity, ParticleFields<D>& fields,
                        RunScalars& scalars) = 0;
    // The name of the stored field attach() bound the velocity to ("" if none): a distributed
    // run refreshes the ghosts' velocities through it when a model reads its neighbours'.
    virtual std::string velocityField() const { return ""; }
    // Chooses Δt_n at level `step` (freshStart: the first level of a run that did not restart);
    // a collapse below 1e-6 of the first step, or a non-finite step, is a timeStepCollapse.
    virtual ForceStatus chooseTimeStep(long step, bool freshStart, const WaveSpeedBound& bound) = 0;
    // Δt_n, the step from the current level.
    virtual double deltaT() const = 0;
    // The velocity at the time level, v^n, from the stored velocity and a^n.
    virtual void synchronise(const std::vector<Vec<D>>& acceleration,
                             std::vector<Vec<D>>& velocityAtLevel) const = 0;
    // x^n -> x^{n+1} and the stored velocity with it, over `dt` (0 ends the run: nothing
    // moves); fixed particles keep x and v = 0.
    virtual void advance(double dt, const std::vector<Vec<D>>& acceleration,
                         const std::vector<std::uint8_t>& fixed, std::vector<Vec<D>>& x) = 0;
};

} // namespace sph
