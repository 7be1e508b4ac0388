// `staticState`: whether a run with kinetic damping came to rest, by the criterion of
// docs/theory/geotechnics.md §E2. With T the run's endTime and u(t) the largest displacement
// of any particle, Δ3 = u(3T/4) − u(T/2) and Δ4 = u(T) − u(3T/4) are how far the most
// displaced particle got in the third and in the last quarter of the run. The run is at rest if
// Δ4 < ratio Δ3 or Δ4 < tolerance: its motion dies out, as dynamic relaxation does while it
// converges, or is below what round-off leaves of a relaxed state. A
// mechanism that keeps moving (a slope that fails) keeps Δ4 near Δ3 if the resets hold it to a
// creep, or beyond if it runs away.
// Keys:
//   ratio     | the threshold on Δ4/Δ3, in (0, 1]                     | 0.9
//   tolerance | a growth that counts as none [m], >= 0                 | 1e-4 of the mean
//             |                                                        | particle spacing
// summary.json: displacementThirdQuarter, displacementLastQuarter [m], displacementRatio
// (Δ4/Δ3), largestDisplacement (u(T)), dampedLastQuarter (the energy kinetic damping removed
// in it), atRest (1 or 0), and the verdict ("at rest", "not at rest", or "undecided" when the
// run stopped before endTime). No table: `energy` tabulates `damped` over time.
#include "core/Format.hpp"
#include "functionObjects/FunctionObject.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

namespace sph
{

template <int D> class StaticState : public FunctionObject<D>
{
public:
    static std::string description()
    {
        return "Whether a run with kinetic damping came to rest: how far the most displaced "
               "particle moved in the last quarter of the run against the third quarter "
               "(docs/theory/geotechnics.md §E2).";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::real("ratio", "the run is at rest if the largest displacement "
                                    "grew in the last quarter by less than ratio "
                                    "times its growth in the third quarter")
                     .range(0.0, 1.0, false, true)
                     .defaultValue("0.9"))
            .add(Key::real("tolerance", "a growth of the largest displacement over a quarter "
                                        "that counts as none [m] (default: 1e-4 of the mean "
                                        "particle spacing, the jitter of a relaxed state)")
                     .nonNegative()
                     .optional());
    }

    StaticState(const Params& params, const typename FunctionObject<D>::Args& args)
        : FunctionObject<D>(args.name), ratio_(params.real("ratio"))
    {
        if (!args.kineticDamping)
        {
            params.fail("type",
                        "staticState judges a run that is taken to rest by kinetic "
                        "damping, and this run has none (an undamped run does not come "
                        "to rest)",
                        {"Add 'kineticDamping yes;' to timeIntegration in system/sphSchemes, "
                         "e.g. timeIntegration { type leapfrog; kineticDamping yes; }"});
        }
        const double T = args.endTime;
        marks_ = {0.5 * T, 0.75 * T, T};
        tolerance_ =
            params.has("tolerance") ? params.real("tolerance") : 1e-4 * meanSpacing(*args.initial);
    }

    bool distributable() const override { return true; } // ParticleRanks
    // The marks are not landing targets (no nextWriteTime): they move with endTime, and a run
    // stopped at an earlier endTime and continued must take the steps of the uninterrupted
    // run. Each mark is recorded at the first level at or after it.
    void start(double startTime, bool restarted) override
    {
        // Continued with another endTime: the quarters are new; those already behind the
        // restart cannot be measured any more.
        lost_ = restarted && otherEnd_ && marks_[0] < startTime * (1.0 - 1e-12);
    }

    bool needsEnergy(long, double time) const override { return due(time); }
    void execute(const StepState<D>& state) override
    {
        if (lost_ || !state.energy || !due(state.time))
        {
            return;
        }
        const double largest = largestDisplacement(state);
        while (due(state.time))
        {
            displacement_[next_] = largest;
            damped_[next_] = state.energy->damped;
            ++next_;
        }
    }

    std::map<std::string, double> results() const override
    {
        if (next_ < 3)
        {
            return {};
        }
        return {{"displacementThirdQuarter", third()},
                {"displacementLastQuarter", last()},
                {"displacementRatio", ratio()},
                {"largestDisplacement", displacement_[2]},
                {"dampedLastQuarter", damped_[2] - damped_[1]},
                {"atRest", atRest() ? 1.0 : 0.0}};
    }
    std::map<std::string, std::string> textResults() const override
    {
        return {{"verdict", next_ < 3 ? "undecided" : atRest() ? "at rest" : "not at rest"}};
    }
    std::vector<std::string> report() const override
    {
        if (lost_)
        {
            return {this->name() + ": undecided (restarted with another endTime, " +
                    formatNumber(marks_[2]) + " s, after half of it: run it from the start)"};
        }
        if (next_ < 3)
        {
            return {this->name() + ": undecided (the run stopped before endTime, " +
                    formatNumber(marks_[2]) + " s)"};
        }
        char line[320];
        std::snprintf(line, sizeof line,
                      "%s: the largest displacement (%.4g m at the end) grew by %.4g m in the "
                      "third quarter of the run and by %.4g m in the last (ratio %.3f; at rest if "
                      "below %.3g times the third quarter's, or below %.3g m): %s",
                      this->name().c_str(), displacement_[2], third(), last(),
                      ratio(), ratio_, tolerance_,
                      atRest() ? "at rest" : "not at rest");
        return {line};
    }

    void saveState(std::map<std::string, double>& state) const override
    {
        state["next"] = static_cast<double>(next_);
        state["endTime"] = marks_[2];
        for (std::size_t i = 0; i < 3; ++i)
        {
            state["displacement" + std::to_string(i)] = displacement_[i];
            state["damped" + std::to_string(i)] = damped_[i];
        }
    }
    void restoreState(const std::map<std::string, double>& state) override
    {
        otherEnd_ = state.at("endTime") != marks_[2];
        if (otherEnd_)
        {
            return;
        }
        next_ = static_cast<std::size_t>(state.at("next"));
        for (std::size_t i = 0; i < 3; ++i)
        {
            displacement_[i] = state.at("displacement" + std::to_string(i));
            damped_[i] = state.at("damped" + std::to_string(i));
        }
    }

private:
    // The level at or after the next mark (the solver's own end test: within 1e-12 of it).
    bool due(double time) const { return next_ < 3 && time >= marks_[next_] * (1.0 - 1e-12); }
    double third() const { return displacement_[1] - displacement_[0]; }
    double last() const { return displacement_[2] - displacement_[1]; }
    double ratio() const { return third() > 0.0 ? last() / third() : 0.0; } // Δ4/Δ3
    bool atRest() const { return last() < std::max(ratio_ * third(), tolerance_); }

    static double meanSpacing(const ParticleSet<D>& p)
    {
        double sum = 0.0;
        for (const double V : p.V0)
        {
            sum += std::pow(V, 1.0 / D);
        }
        return p.V0.empty() ? 0.0 : sum / static_cast<double>(p.V0.size());
    }

    static double largestDisplacement(const StepState<D>& state)
    {
        const ParticleSet<D>& p = state.particles;
        const ParticleRanks& ranks = state.rankView();
        std::vector<double> largest{0.0};
        for (std::size_t a = 0; a < p.size(); ++a)
        {
            if (ranks.counts(a))
            {
                largest[0] = std::max(largest[0], (p.x[a] - p.X[a]).norm());
            }
        }
        ranks.maximum(largest);
        return largest[0];
    }

    double ratio_;
    double tolerance_ = 0.0;
    std::array<double, 3> marks_{};        // T/2, 3T/4, T
    std::array<double, 3> displacement_{}; // u at the levels at or after them
    std::array<double, 3> damped_{};       // K_damped there
    std::size_t next_ = 0;                 // the next mark to record
    bool otherEnd_ = false;                // restored from a run with another endTime
    bool lost_ = false;                    // ... whose quarters had begun: no verdict
};

SPH_REGISTER_DIM_MODEL(FunctionObject, StaticState, "staticState");

} // namespace sph
