// `leapfrog`: the scheme of seed eqs. (15)-(16) (spec §10), velocities at half steps:
//
//   v^{n+1/2} = v^{n-1/2} + ½(Δt_{n-1} + Δt_n) a^n,   x^{n+1} = x^n + Δt_n v^{n+1/2},
//   v^{1/2} = v^0 + ½Δt_0 a^0 at the start,          v^n = v^{n-1/2} + ½Δt_{n-1} a^n,
//   Δt_n = α h / max_a c(F_a).
//
// Symplectic for a constant step, second order, explicit: one force evaluation per step.
// Split at a level where the reference moves (updatedLagrangian's splitKick, gradF-plastic.md
// §G20): v^n = v^{n-1/2} + ½Δt_{n-1} a^n_close, then v^{n+1/2} = v^n + ½Δt_n a^n.
//
// The step's bound (docs/theory/timeStep.md):
//   stepBound waveSpeed: Δt_n = courant h / max_a c(F_a) (seed eq. 17, plasticity.md (P2.5)-(P2.7)),
//                        recomputed every timeStepUpdateInterval steps;
//   stepBound operator:  Δt_0 as above, κ = ω̃_0 Δt_0, then Δt_n = κ / ω̃_n at every probe,
//                        capped at courant h / c0 with walls (§T4); ω̃ the operator's largest
//                        frequency measured by the solver's probe (§T3).
//
// Keys:
//   stepBound       | waveSpeed or operator                                  | waveSpeed
//   probeInterval   | steps between probes, >= 1; with waveSpeed, given: the | 10 (operator),
//                   | probe only reports ω̃ Δt (progress line)               | none (waveSpeed)
//   probeIterations | power iterations per probe, >= 1                      | 2
//   kineticDamping  | yes: every velocity is set to zero where the total    | no
//                   | kinetic energy of the half steps passes a peak (a      |
//                   | static state by dynamic relaxation; geotechnics.md §E2)|
#include "particles/Parallel.hpp"
#include "timeIntegration/TimeIntegration.hpp"

#include <cmath>
#include <cstdio>

namespace sph
{

template <int D>
class Leapfrog : public TimeIntegration<D>
{
public:
    static std::string description()
    {
        return "Leapfrog (kick-drift with half-step velocities, seed eqs. 15-16): second "
               "order, one force evaluation per step, Δt = courant h / max c, or (stepBound "
               "operator) kept at the first step's margin to the forces' measured largest "
               "frequency.";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::word("stepBound", "what bounds the step: waveSpeed (courant h / c) or "
                                        "operator (the measured largest frequency of the "
                                        "forces, docs/theory/timeStep.md)")
                     .choices({"waveSpeed", "operator"})
                     .defaultValue("waveSpeed"))
            .add(Key::integer("probeInterval", "steps between measurements of the largest "
                                               "frequency; with waveSpeed they are only "
                                               "reported (omega dt on the progress line); "
                                               "default 10 with operator")
                     .min(1)
                     .optional())
            .add(Key::integer("probeIterations", "power iterations per measurement (stepBound "
                                                 "operator); the first level makes 50")
                     .min(1)
                     .defaultValue("2"))
            .add(Key::boolean("kineticDamping",
                              "set every velocity to zero at each peak of the kinetic energy, "
                              "to reach a static state (dynamic relaxation: the motion is not "
                              "physical, its end state is; docs/theory/geotechnics.md §E2)")
                     .defaultValue("no"));
    }

    Leapfrog(const Params& params, const typename TimeIntegration<D>::Args& args)
        : courant_(args.courant), interval_(args.timeStepUpdateInterval),
          kineticDamping_(params.boolean("kineticDamping"))
    {
        controlsStep_ = params.word("stepBound") == "operator";
        if (controlsStep_ || params.has("probeInterval"))
        {
            probe_ = OperatorProbeRequest{
                params.has("probeInterval") ? params.integer("probeInterval") : 10,
                static_cast<int>(params.integer("probeIterations")),
                params.location(controlsStep_ ? "stepBound" : "probeInterval"), controlsStep_};
        }
        else if (params.given("probeIterations"))
        {
            params.fail("probeIterations", "probeIterations applies only where a probe runs",
                        {"Add 'stepBound operator;' (the step follows the probe) or "
                         "'probeInterval N;' (the probe only reports), or remove "
                         "probeIterations."});
        }
        if (controlsStep_ && interval_ != 1)
        {
            params.fail("stepBound", "stepBound operator changes the step at its probes "
                                     "(every probeInterval steps); timeStepUpdateInterval "
                                     "(controlDict) is " + std::to_string(interval_),
                        {"Remove timeStepUpdateInterval from controlDict, or use stepBound "
                         "waveSpeed."});
        }
    }

    std::optional<OperatorProbeRequest> operatorProbe() const override { return probe_; }
    void setOperatorFrequency(OperatorFrequency<D> frequency) override
    {
        frequency_ = std::move(frequency);
    }

    std::string velocityField() const override { return "velocityHalfStep"; }
    bool kineticDamping() const override { return kineticDamping_; }
    // v^{n+1} = 0: the stored velocity becomes the level's (zero), and the next kick is the
    // start's half kick, v^{n+3/2} = ½Δt a^{n+1}.
    void restAtLevel() override
    {
        for (Vec<D>& v : *v_)
        {
            v.setZero();
        }
        halfStep_ = false;
    }

    void attach(std::vector<Vec<D>>& velocity, ParticleFields<D>& fields,
                RunScalars& scalars) override
    {
        v_ = &velocity;
        fields.bind(FieldSpec::vector(velocityField(), "v^{n-1/2} of the leapfrog (v^0 "
                                                          "before the first step) [m/s]")
                        .restart(),
                    velocity);
        scalars.bind("deltaT", deltaT_);
        scalars.bind("previousDeltaT", previousDeltaT_);
        scalars.bind("firstDeltaT", firstDeltaT_);
        scalars.bind("halfStepVelocity", halfStep_);
        if (probe_)
        {
            mode_.assign(velocity.size(), Vec<D>::Zero()); // a field: one per particle
            fields.bind(FieldSpec::vector("operatorMode", "the mode of the largest frequency "
                                                          "of the forces, as the last probe "
                                                          "left it (stepBound operator)")
                            .restart(),
                        mode_);
            scalars.bind("operatorMargin", margin_);
            scalars.bind("operatorFrequency", omega_);
        }
    }

    ForceStatus chooseTimeStep(long step, bool freshStart, const WaveSpeedBound& bound) override
    {
        if (controlsStep_)
        {
            return chooseFromOperator(step, freshStart, bound);
        }
        if (probe_ && (freshStart || step % probe_->interval == 0))
        {
            measure(freshStart);
        }
        if (!freshStart && !(interval_ > 0 && step % interval_ == 0))
        {
            return {};
        }
        const double stable = courant_ * bound.h / bound.maxWaveSpeed();
        if (freshStart)
        {
            firstDeltaT_ = stable;
        }
        if (!(stable > 1e-6 * firstDeltaT_) || !std::isfinite(stable))
        {
            return ForceStatus::failed(FailureKind::timeStepCollapse,
                                       static_cast<long>(bound.fastestParticle()), stable,
                                       "time step (collapsed to " + std::to_string(stable) +
                                           " s from " + std::to_string(firstDeltaT_) +
                                           " s; the largest wave speed is here)");
        }
        deltaT_ = stable;
        return {};
    }

    double deltaT() const override { return deltaT_; }

    std::string stepNote() const override
    {
        if (!probe_)
        {
            return "";
        }
        char note[64];
        std::snprintf(note, sizeof note, "omega dt = %.3f", omega_ * deltaT_);
        return note;
    }

    void synchronise(const std::vector<Vec<D>>& a, std::vector<Vec<D>>& vn) const override
    {
        const std::vector<Vec<D>>& v = *v_;
        const double factor = halfStep_ ? 0.5 * previousDeltaT_ : 0.0;
        const std::size_t n = v.size();
#pragma omp parallel for schedule(static) if (useThreads(n))
        for (std::size_t i = 0; i < n; ++i)
        {
            vn[i] = v[i] + factor * a[i];
        }
    }

    bool splitsKicks() const override { return true; }

    // v^n = v^{n-1/2} + ½Δt_{n-1} a_close; the next advance() kicks ½Δt_n from v^n, as at the
    // start of a run (a level reached at rest, after kinetic damping's reset, has v^n already).
    void closeAtLevel(const std::vector<Vec<D>>& closing) override
    {
        if (!halfStep_)
        {
            return;
        }
        std::vector<Vec<D>>& v = *v_;
        const double factor = 0.5 * previousDeltaT_;
        const std::size_t n = v.size();
#pragma omp parallel for schedule(static) if (useThreads(n))
        for (std::size_t i = 0; i < n; ++i)
        {
            v[i] += factor * closing[i];
        }
        halfStep_ = false;
    }

    void advance(double dt, const std::vector<Vec<D>>& a, const std::vector<std::uint8_t>& fixed,
                 std::vector<Vec<D>>& x) override
    {
        std::vector<Vec<D>>& v = *v_;
        const double kick = halfStep_ ? 0.5 * (previousDeltaT_ + dt) : 0.5 * dt;
        const std::size_t n = v.size();
#pragma omp parallel for schedule(static) if (useThreads(n))
        for (std::size_t i = 0; i < n; ++i)
        {
            if (fixed[i])
            {
                v[i].setZero();
                continue;
            }
            v[i] += kick * a[i];
            x[i] += dt * v[i];
        }
        halfStep_ = true;
        previousDeltaT_ = dt;
    }

private:
    // (T4.1): the first level takes the wave-speed step and measures the margin κ = ω̃_0 Δt_0
    // that it leaves; every probe after it sets Δt = κ / ω̃.
    ForceStatus chooseFromOperator(long step, bool freshStart, const WaveSpeedBound& bound)
    {
        if (!freshStart && step % probe_->interval != 0)
        {
            return {};
        }
        const typename OperatorProbe<D>::Result measured = measure(freshStart);
        double stable = 0.0;
        if (freshStart)
        {
            stable = courant_ * bound.h / bound.maxWaveSpeed();
            firstDeltaT_ = stable;
            margin_ = omega_ * stable;
        }
        else if (margin_ > 0.0 && omega_ > 0.0)
        {
            stable = std::min(margin_ / omega_, bound.wallDeltaT);
        }
        else
        {
            // Nothing that vibrates was found (every particle fixed, or no neighbours): the
            // wave-speed step.
            stable = courant_ * bound.h / bound.maxWaveSpeed();
        }
        if (!(stable > 1e-6 * firstDeltaT_) || !std::isfinite(stable))
        {
            return ForceStatus::failed(FailureKind::timeStepCollapse,
                                       static_cast<long>(measured.where), stable,
                                       "time step (collapsed to " + std::to_string(stable) +
                                           " s from " + std::to_string(firstDeltaT_) +
                                           " s; the largest frequency of the forces, " +
                                           std::to_string(omega_) + " 1/s, has its mode here)");
        }
        deltaT_ = stable;
        return {};
    }

    // ω̃ from the solver's probe (§T3): from a random start at the first level the power
    // iteration needs many products, later the kept mode a few.
    typename OperatorProbe<D>::Result measure(bool freshStart)
    {
        const typename OperatorProbe<D>::Result measured =
            frequency_(freshStart ? firstIterations : probe_->iterations, mode_);
        omega_ = measured.omega;
        return measured;
    }

    static constexpr int firstIterations = 50;

    double courant_;
    long interval_;
    std::optional<OperatorProbeRequest> probe_; // a probe runs (stepBound operator, or probeInterval)
    bool controlsStep_ = false;                 // stepBound operator: the step follows it
    bool kineticDamping_ = false;
    OperatorFrequency<D> frequency_;
    std::vector<Vec<D>> mode_;    // y of §T3 (restart data)
    double margin_ = 0.0;         // κ = ω̃_0 Δt_0
    double omega_ = 0.0;          // ω̃ of the last probe
    std::vector<Vec<D>>* v_ = nullptr;
    double deltaT_ = 0.0;         // Δt_n
    double previousDeltaT_ = 0.0; // Δt_{n-1}
    double firstDeltaT_ = 0.0;    // Δt_0: a step below 1e-6 of it is a collapse
    bool halfStep_ = false;       // the velocity holds v^{n-1/2} (false: v^0 at the start)
};

SPH_REGISTER_DIM_MODEL(TimeIntegration, Leapfrog, "leapfrog");

} // namespace sph
