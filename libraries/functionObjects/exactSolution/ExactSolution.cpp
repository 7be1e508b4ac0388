// `exactSolution`: compares a probe with an analytic solution and keeps running error norms.
// Solutions:
//   fixedFreeBar (1D): the bar fixed at its first particle, free at the other end, at rest
//     except a uniformly moving end segment (the Dyka bar, spec §11.1). Exact d'Alembert
//     solution u(ξ,t) = (Φ(ξ+ct) - Φ(ξ-ct))/(2c), v = ½(ṽ(ξ+ct) + ṽ(ξ-ct)), ṽ the initial
//     velocity extended odd about the fixed end and even about the free end (period 4L), Φ its
//     antiderivative; ξ = X - X(fixed end).
// Keys:
//   solution   | fixedFreeBar                                                  | required
//   point      | probe location (initial position) [m]           | the free end
//   length     | bar length L from the fixed particle [m]        | from the particle volumes
//   waveSpeed  | c [m/s]                                         | the material's, at F = I
//   velocity   | initial velocity of the moving segment [m/s]    | from the initial state
//   loadedFrom | where the moving segment starts, x_s [m]        | from the initial state
// By default everything is read off the case, so the solution matches the discretised
// initial condition at every resolution (x_s = half a spacing before the first moving
// particle; with half-volume ends L is the distance between the end particles).
// Columns: u_numeric u_exact u_error v_numeric v_exact u_periodMean. The run summary reports
// the L∞ and RMS errors of u over the run, absolute and relative to the exact amplitude
// V (L - x_s)/c, and the creep: the mean of u over each complete NUMERICAL period (between
// consecutive downward zero crossings; the exact mean is 0), which a mean over the exact
// period would bias by the period error.
#include "core/Format.hpp"
#include "functionObjects/FunctionObjectModel.hpp"
#include "functionObjects/PeriodTracker.hpp"

#include <cmath>
#include <sstream>

namespace sph
{

// The exact solution of the fixed-free bar with a moving end segment.
class FixedFreeBar
{
public:
    FixedFreeBar(double length, double waveSpeed, double velocity, double loadedFrom)
        : L_(length), c_(waveSpeed), V_(velocity), xs_(loadedFrom)
    {
    }
    double displacement(double xi, double t) const
    {
        return (Phi(xi + c_ * t) - Phi(xi - c_ * t)) / (2.0 * c_);
    }
    double velocity(double xi, double t) const
    {
        return 0.5 * (extended(xi + c_ * t) + extended(xi - c_ * t));
    }
    double amplitude() const { return std::abs(V_) * (L_ - xs_) / c_; }
    double period() const { return 4.0 * L_ / c_; }

private:
    // s mapped into [-2L, 2L).
    double reduce(double s) const
    {
        const double period = 4.0 * L_;
        double r = std::fmod(s + 2.0 * L_, period);
        if (r < 0.0)
        {
            r += period;
        }
        return r - 2.0 * L_;
    }
    double extended(double s) const
    {
        s = reduce(s);
        const double sign = s < 0.0 ? -1.0 : 1.0;
        s = std::abs(s);
        if (s > L_)
        {
            s = 2.0 * L_ - s;
        }
        return s > xs_ ? sign * V_ : 0.0;
    }
    double Phi(double s) const
    {
        s = std::abs(reduce(s)); // Φ is even and 4L-periodic
        if (s <= L_)
        {
            return V_ * std::max(0.0, s - xs_);
        }
        return V_ * std::max(0.0, L_ - xs_) + V_ * std::max(0.0, std::min(s - L_, L_ - xs_));
    }

    double L_;
    double c_;
    double V_;
    double xs_;
};

template <int D> class ExactSolution : public FunctionObjectModel<D>
{
public:
    static std::string description()
    {
        return "Probe against an analytic solution with running L-inf and RMS errors "
               "(fixedFreeBar: the Dyka bar, spec §11.1).";
    }
    static Schema schema()
    {
        return FunctionObjectModel<D>::commonSchema()
            .add(Key::word("solution", "the analytic solution").choices({"fixedFreeBar"}))
            .add(Key::vector("point", "probe location, by initial position [m] (default: the "
                                      "free end)")
                     .optional())
            .add(
                Key::real("length", "bar length from the fixed particle [m]").positive().optional())
            .add(Key::real("waveSpeed", "wave speed c [m/s]").positive().optional())
            .add(Key::real("velocity", "initial velocity of the moving segment [m/s]").optional())
            .add(Key::real("loadedFrom", "start x_s of the moving segment [m]").optional());
    }

    ExactSolution(const Params& params, const typename FunctionObject<D>::Args& args)
        : FunctionObjectModel<D>(params, args)
    {
        const ParticleSet<D>& p = *args.initial;
        // The bar: the body holding the probe.
        std::size_t probe = 0;
        double target = 0.0;
        bool atEnd = !params.has("point");
        if (!atEnd)
        {
            target = params.vector("point")[0];
        }
        double best = std::numeric_limits<double>::max();
        for (std::size_t a = 0; a < p.size(); ++a)
        {
            const double distance = atEnd ? -p.X[a][0] : std::abs(p.X[a][0] - target);
            if (distance < best)
            {
                best = distance;
                probe = a;
            }
        }
        const BodyRange& bar = p.bodies[static_cast<std::size_t>(p.body[probe])];
        if (bar.size() < 3)
        {
            params.fail("solution", "fixedFreeBar needs a bar of at least 3 particles");
        }
        const double spacing = p.V0[bar.begin + 1];
        const double fixedEnd = p.X[bar.begin][0];
        probe_ = probe;
        xi_ = p.X[probe][0] - fixedEnd;
        const std::size_t last = bar.end - 1;
        const double length = params.has("length")
                                  ? params.real("length")
                                  : p.X[last][0] + (p.V0[last] - 0.5 * spacing) - fixedEnd;
        const double waveSpeed =
            params.has("waveSpeed")
                ? params.real("waveSpeed")
                : (*args.materials)[static_cast<std::size_t>(p.body[probe])]->waveSpeed(
                      Mat<D>::Identity());
        // The moving segment from the initial velocities: at rest up to some particle, then
        // one uniform velocity to the end.
        double velocity = p.v[last][0];
        std::size_t firstMoving = last;
        while (firstMoving > bar.begin && p.v[firstMoving - 1][0] == velocity)
        {
            --firstMoving;
        }
        if (!params.has("velocity") || !params.has("loadedFrom"))
        {
            for (std::size_t a = bar.begin; a < firstMoving; ++a)
            {
                if (p.v[a][0] != 0.0)
                {
                    params.fail("solution",
                                "fixedFreeBar: the bar must be at rest except a "
                                "uniformly moving end segment (particle " +
                                    std::to_string(a) + " moves)",
                                {"Give 'velocity' and 'loadedFrom' to describe the load "
                                 "explicitly."});
                }
            }
        }
        if (params.has("velocity"))
        {
            velocity = params.real("velocity");
        }
        const double loadedFrom = params.has("loadedFrom")
                                      ? params.real("loadedFrom") - fixedEnd
                                      : p.X[firstMoving][0] - 0.5 * spacing - fixedEnd;
        if (!(loadedFrom >= 0.0 && loadedFrom < length))
        {
            params.fail("solution", "fixedFreeBar: the moving segment must start inside the bar");
        }
        solution_ = std::make_unique<FixedFreeBar>(length, waveSpeed, velocity, loadedFrom);
        description_ = "L=" + formatNumber(length, 5) + " m, c=" + formatNumber(waveSpeed, 5) +
                       " m/s, V=" + formatNumber(velocity, 5) +
                       " m/s, x_s=" + formatNumber(loadedFrom, 5) + " m, probe " +
                       std::to_string(probe) + " at xi=" + formatNumber(xi_, 5) + " m, period " +
                       formatNumber(solution_->period(), 5) + " s, amplitude " +
                       formatNumber(solution_->amplitude(), 5) + " m";
        this->setColumns(
            {"u_numeric", "u_exact", "u_error", "v_numeric", "v_exact", "u_periodMean"});
    }

    bool distributable() const override { return true; } // ParticleRanks

    void execute(const StepState<D>& state) override
    {
        // The probe's displacement and velocity, from the rank that owns it.
        const std::vector<double> probe =
            state.rankView().fromOwners({probe_}, 2, [&](std::size_t a, double* out) {
                out[0] = state.particles.x[a][0] - state.particles.X[a][0];
                out[1] = state.velocity[a][0];
            });
        const double u = probe[0];
        const double exact = solution_->displacement(xi_, state.time);
        const double error = u - exact;
        maxError_ = std::max(maxError_, std::abs(error));
        sumSquares_ += error * error;
        ++samples_;
        periods_.add(state.time, u);
        if (this->rowDue(state.time, state.deltaT))
        {
            this->writeRow(state.time, state.deltaT,
                           {u, exact, error, probe[1],
                            solution_->velocity(xi_, state.time), periods_.lastMean()});
        }
    }

    std::vector<std::string> report() const override
    {
        const double rms = samples_ > 0 ? std::sqrt(sumSquares_ / samples_) : 0.0;
        const double amplitude = solution_->amplitude();
        std::vector<std::string> lines{
            this->name() + ": fixedFreeBar " + description_,
            this->name() + ": displacement error Linf " + formatNumber(maxError_, 5) + " m (" +
                formatNumber(maxError_ / amplitude, 5) + " of the amplitude), RMS " +
                formatNumber(rms, 5) + " m (" + formatNumber(rms / amplitude, 5) + ")"};
        if (periods_.periods() > 0)
        {
            lines.push_back(
                this->name() + ": " + std::to_string(periods_.periods()) +
                " numerical periods, the last " + formatNumber(periods_.lastPeriod(), 5) + " s (" +
                formatNumber(100.0 * (periods_.lastPeriod() / solution_->period() - 1.0), 5) +
                " % from 4L/c); mean displacement over it " + formatNumber(periods_.lastMean(), 5) +
                " m (" + formatNumber(periods_.lastMean() / amplitude, 5) +
                " of the amplitude), largest |mean| " +
                formatNumber(periods_.maxAbsMean() / amplitude, 5));
        }
        return lines;
    }
    std::map<std::string, double> results() const override
    {
        const double amplitude = solution_->amplitude();
        const double rms = samples_ > 0 ? std::sqrt(sumSquares_ / samples_) : 0.0;
        return {{"linfError", maxError_},
                {"rmsError", rms},
                {"amplitude", amplitude},
                {"relativeLinfError", maxError_ / amplitude},
                {"relativeRmsError", rms / amplitude},
                {"exactPeriod", solution_->period()},
                {"periods", static_cast<double>(periods_.periods())},
                {"lastPeriod", periods_.lastPeriod()},
                {"relativePeriodMean", periods_.lastMean() / amplitude},
                {"relativeMaxPeriodMean", periods_.maxAbsMean() / amplitude}};
    }
    void saveState(std::map<std::string, double>& state) const override
    {
        FunctionObjectModel<D>::saveState(state);
        state["maxError"] = maxError_;
        state["sumSquares"] = sumSquares_;
        state["samples"] = static_cast<double>(samples_);
        periods_.save(state, "periods");
    }
    void restoreState(const std::map<std::string, double>& state) override
    {
        FunctionObjectModel<D>::restoreState(state);
        maxError_ = state.at("maxError");
        sumSquares_ = state.at("sumSquares");
        samples_ = static_cast<long>(state.at("samples"));
        periods_.restore(state, "periods");
    }

private:
    // What the solution was built from (read off the case unless given), for the run header.
    std::vector<std::string> summaryExtras() const override { return {description_}; }

    std::unique_ptr<FixedFreeBar> solution_;
    std::size_t probe_ = 0;
    double xi_ = 0.0;
    std::string description_;
    double maxError_ = 0.0;
    double sumSquares_ = 0.0;
    long samples_ = 0;
    PeriodTracker periods_; // creep: the mean of u over each numerical period
};

SPH_REGISTER_DIM_MODEL_FOR(FunctionObject, ExactSolution, "exactSolution", 1);

} // namespace sph
