// `leapfrog`: the scheme of seed eqs. (15)-(16) (spec §10), velocities at half steps:
//
//   v^{n+1/2} = v^{n-1/2} + ½(Δt_{n-1} + Δt_n) a^n,   x^{n+1} = x^n + Δt_n v^{n+1/2},
//   v^{1/2} = v^0 + ½Δt_0 a^0 at the start,          v^n = v^{n-1/2} + ½Δt_{n-1} a^n,
//   Δt_n = α h / max_a c(F_a).
//
// Symplectic for a constant step, second order, explicit: one force evaluation per step.
#include "particles/Parallel.hpp"
#include "timeIntegration/TimeIntegration.hpp"

#include <cmath>

namespace sph
{

template <int D>
class Leapfrog : public TimeIntegration<D>
{
public:
    static std::string description()
    {
        return "Leapfrog (kick-drift with half-step velocities, seed eqs. 15-16): second "
               "order, one force evaluation per step, Δt = courant h / max c.";
    }
    static Schema schema() { return Schema(); }

    Leapfrog(const Params&, const typename TimeIntegration<D>::Args& args)
        : courant_(args.courant), interval_(args.timeStepUpdateInterval)
    {
    }

    std::string velocityField() const override { return "velocityHalfStep"; }

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
    }

    ForceStatus chooseTimeStep(long step, bool freshStart, const WaveSpeedBound& bound) override
    {
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
    double courant_;
    long interval_;
    std::vector<Vec<D>>* v_ = nullptr;
    double deltaT_ = 0.0;         // Δt_n
    double previousDeltaT_ = 0.0; // Δt_{n-1}
    double firstDeltaT_ = 0.0;    // Δt_0: a step below 1e-6 of it is a collapse
    bool halfStep_ = false;       // the velocity holds v^{n-1/2} (false: v^0 at the start)
};

SPH_REGISTER_DIM_MODEL(TimeIntegration, Leapfrog, "leapfrog");

} // namespace sph
