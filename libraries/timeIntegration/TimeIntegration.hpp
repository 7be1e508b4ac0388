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
#include "core/SourceLocation.hpp"
#include "particles/ParticleFields.hpp"
#include "stabilisation/Stabilisation.hpp"
#include "timeIntegration/OperatorProbe.hpp"

#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
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
    // The longest step the rigid walls allow when the step does not follow the wave speed
    // (docs/theory/timeStep.md §T4): courant h / c0; infinite without walls.
    double wallDeltaT = std::numeric_limits<double>::infinity();
};

// What an integrator that measures the operator's largest frequency asks of the solver
// (docs/theory/timeStep.md §T3): a probe every `interval` steps of `iterations` products, and
// where it asked for it (for the solver's refusals: a viscosity, contact, several ranks).
struct OperatorProbeRequest
{
    long interval = 10;
    int iterations = 2;
    SourceLocation where;
    bool controlsStep = true; // the step follows it (else it is only reported)
};

// The solver's probe: `iterations` power iterations from the kept mode (OperatorProbe<D>::run at
// the level's positions and forces).
template <int D>
using OperatorFrequency =
    std::function<typename OperatorProbe<D>::Result(int iterations, std::vector<Vec<D>>& mode)>;

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
    // Whether the step follows the operator's measured largest frequency (then the solver hands
    // over its probe once, before the first step, and chooseTimeStep() calls it at the probes).
    virtual std::optional<OperatorProbeRequest> operatorProbe() const { return std::nullopt; }
    virtual void setOperatorFrequency(OperatorFrequency<D> probe) { (void)probe; }
    // Whether the solver resets every velocity to zero at each peak of the kinetic energy
    // (kinetic damping, docs/theory/geotechnics.md §E2: a static state by dynamic relaxation).
    virtual bool kineticDamping() const { return false; }
    // Kinetic damping's reset, after a step x^n -> x^{n+1}: every velocity is zero at the level
    // x^{n+1}, and the next step starts from rest there as a run starts (only called when
    // kineticDamping() is true).
    virtual void restAtLevel() {}
    // Whether the kick at a level can be split in two (closeAtLevel()): updatedLagrangian's
    // `splitKick` needs it.
    virtual bool splitsKicks() const { return false; }
    // The kick split at a move of the reference (docs/theory/gradF-plastic.md §G20): the step
    // that ended at this level closes with `closingAcceleration` (the forces of the reference
    // that step began with), so the stored velocity becomes v^n; the next advance() opens from
    // it with the level's own acceleration (that of the moved reference). Fixed particles' are
    // zero. Called only where splitsKicks() is true.
    virtual void closeAtLevel(const std::vector<Vec<D>>& closingAcceleration)
    {
        (void)closingAcceleration;
        throw std::logic_error("this time integrator cannot split its kick at a level");
    }
    // A few words on the current step for the run log's progress line ("" for none).
    virtual std::string stepNote() const { return ""; }
    // The velocity at the time level, v^n, from the stored velocity and a^n.
    virtual void synchronise(const std::vector<Vec<D>>& acceleration,
                             std::vector<Vec<D>>& velocityAtLevel) const = 0;
    // x^n -> x^{n+1} and the stored velocity with it, over `dt` (0 ends the run: nothing
    // moves); fixed particles keep x and v = 0.
    virtual void advance(double dt, const std::vector<Vec<D>>& acceleration,
                         const std::vector<std::uint8_t>& fixed, std::vector<Vec<D>>& x) = 0;
};

} // namespace sph
