// `stabilityMonitor`: numbers that show a scheme going unstable before it fails (issue 4).
// Columns:
//   zeroEnergyIndicator  max_a Σ_b Ŵ_ab |x_ba - F_a X_ba| / h: how far the neighbours are
//                        from where the particle's own deformation gradient puts them (0 for
//                        a linear field, O(|∇F| h) for a smooth one; zero-energy / hourglass
//                        patterns make it grow). Ŵ_ab = W_ab V^r_b / Σ_e W_ae V^r_e over the
//                        reference neighbours. The total map F (from the initial positions X)
//                        is used, not the increment f from x^r: when the reference moves every
//                        step x = x^r at evaluation, and a pattern frozen into F^r would be
//                        invisible to f. In total-Lagrangian form X = x^r and the two agree.
//   worstParticle        where that maximum is
//   minJ maxJ            extremes of det F
//   minDistanceRatio     the smallest distance between neighbours over the initial spacing
//                        (particles clumping or crossing make it drop towards 0)
// Verdict at the end of the run (log and summary.json `verdict`, `verdictReason`), from the
// worst values over the run, with the bounds the hard cases use (tutorials/hardCases/README.md):
//   stable     closest neighbours >= 0.5 of the initial spacing and indicator <= 0.5
//   unstable   closest neighbours < 0.1 of the initial spacing or indicator > 1 (particles
//              pair up or a zero-energy pattern is as large as the kernel)
//   suspect    in between (large plastic flow legitimately brings neighbours closer: look)
// Where F is not the total map (gradF elasticState moving a plastic material's reference keeps
// F as a dilation frame, docs/theory/gradF-plastic.md §G11) the indicator measures the flow's
// shear, not a pattern: it is still written, and the verdict is the closest pair's alone.
// Keys: writeInterval (see FunctionObject.hpp).
#include "functionObjects/FunctionObjectModel.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace sph
{

template <int D> class StabilityMonitor : public FunctionObjectModel<D>
{
public:
    static std::string description()
    {
        return "Zero-energy-mode indicator, extremes of det F and the smallest neighbour "
               "distance over the initial spacing.";
    }
    static Schema schema() { return FunctionObjectModel<D>::commonSchema(); }

    StabilityMonitor(const Params& params, const typename FunctionObject<D>::Args& args)
        : FunctionObjectModel<D>(params, args), spacing_(initialSpacing(*args.initial)),
          indicatorApplies_(args.totalDeformationGradient)
    {
        this->setColumns(
            {"zeroEnergyIndicator", "worstParticle", "minJ", "maxJ", "minDistanceRatio"});
    }

    bool distributable() const override { return true; } // ParticleRanks

    void execute(const StepState<D>& state) override
    {
        if (!this->rowDue(state.time, state.deltaT))
        {
            return;
        }
        const ParticleSet<D>& p = state.particles;
        const ReferenceConfiguration<D>& ref = state.reference;
        const NeighbourList& list = ref.neighbours;
        const double h = state.kernel.h();
        const ParticleRanks& ranks = state.rankView();
        double indicator = 0.0;
        double worst = std::numeric_limits<double>::infinity(); // global index; none yet
        double minJ = std::numeric_limits<double>::max();
        double maxJ = std::numeric_limits<double>::lowest();
        double minDistance2 = std::numeric_limits<double>::max();
        for (std::size_t a = 0; a < p.size(); ++a)
        {
            if (!ranks.counts(a))
            {
                continue;
            }
            const double J = p.F[a].determinant();
            minJ = std::min(minJ, J);
            maxJ = std::max(maxJ, J);
            double weightSum = 0.0;
            double misfit = 0.0;
            for (std::size_t k = list.begin(a); k < list.end(a); ++k)
            {
                const std::size_t b = list.indices[k];
                const double w = state.kernel.W((ref.x[a] - ref.x[b]).norm()) * ref.V[b];
                weightSum += w;
                const Vec<D> current = p.x[b] - p.x[a];
                misfit += w * (current - p.F[a] * (p.X[b] - p.X[a])).norm();
                if (b != a)
                {
                    minDistance2 = std::min(minDistance2, current.squaredNorm());
                }
            }
            const double value = misfit / (weightSum * h);
            if (value > indicator)
            {
                indicator = value;
                worst = static_cast<double>(ranks.global(a));
            }
        }
        // Over the ranks: the extremes, and the worst particle of least global index (as the
        // serial loop finds it first).
        std::vector<double> largest{indicator, maxJ, -minJ, -minDistance2};
        ranks.maximum(largest);
        std::vector<double> first{largest[0] == indicator ? worst
                                                           : std::numeric_limits<double>::infinity()};
        ranks.minimum(first);
        indicator = largest[0];
        maxJ = largest[1];
        minJ = -largest[2];
        minDistance2 = -largest[3];
        worst = std::isfinite(first[0]) ? first[0] : 0.0;
        if (!haveFirst_)
        {
            first_ = indicator;
            haveFirst_ = true;
        }
        last_ = indicator;
        maxIndicator_ = std::max(maxIndicator_, indicator);
        minDistanceRatio_ = std::min(minDistanceRatio_, std::sqrt(minDistance2) / spacing_);
        lowestJ_ = std::min(lowestJ_, minJ);
        highestJ_ = std::max(highestJ_, maxJ);
        this->writeRow(state.time, state.deltaT,
                       {indicator, worst, minJ, maxJ,
                        std::sqrt(minDistance2) / spacing_});
    }

    std::vector<std::string> report() const override
    {
        char line[256];
        std::snprintf(line, sizeof line,
                      "%s: zero-energy indicator at the end %.3e, largest %.3e; smallest "
                      "neighbour distance / initial spacing %.3f",
                      this->name().c_str(), last_, maxIndicator_, minDistanceRatio_);
        const Verdict v = verdict();
        std::string word = v.word;
        if (word != "stable")
        {
            std::transform(word.begin(), word.end(), word.begin(),
                           [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
        }
        return {line, this->name() + ": verdict " + word + ": " + v.reason};
    }
    std::map<std::string, std::string> textResults() const override
    {
        const Verdict v = verdict();
        return {{"verdict", v.word}, {"verdictReason", v.reason}};
    }
    std::map<std::string, double> results() const override
    {
        return {{"firstIndicator", first_},
                {"finalIndicator", last_},
                {"maxIndicator", maxIndicator_},
                {"indicatorGrowth", first_ > 0.0 ? maxIndicator_ / first_ : 0.0},
                {"minDistanceRatio", minDistanceRatio_},
                {"minJ", lowestJ_},
                {"maxJ", highestJ_}};
    }
    void saveState(std::map<std::string, double>& state) const override
    {
        FunctionObjectModel<D>::saveState(state);
        state["last"] = last_;
        state["first"] = first_;
        state["haveFirst"] = haveFirst_ ? 1.0 : 0.0;
        state["maxIndicator"] = maxIndicator_;
        state["minDistanceRatio"] = minDistanceRatio_;
        state["lowestJ"] = lowestJ_;
        state["highestJ"] = highestJ_;
    }
    void restoreState(const std::map<std::string, double>& state) override
    {
        FunctionObjectModel<D>::restoreState(state);
        last_ = state.at("last");
        first_ = state.at("first");
        haveFirst_ = state.at("haveFirst") != 0.0;
        maxIndicator_ = state.at("maxIndicator");
        minDistanceRatio_ = state.at("minDistanceRatio");
        lowestJ_ = state.at("lowestJ");
        highestJ_ = state.at("highestJ");
    }

private:
    static constexpr double stableDistance = 0.5;
    static constexpr double unstableDistance = 0.1;
    static constexpr double stableIndicator = 0.5;
    static constexpr double unstableIndicator = 1.0;
    struct Verdict
    {
        std::string word;
        std::string reason;
    };
    // The deciding figure: the worse of the two measures against its bounds.
    Verdict verdict() const
    {
        if (minDistanceRatio_ == std::numeric_limits<double>::max())
        {
            return {"unknown", "no level was monitored"};
        }
        char distance[160];
        std::snprintf(distance, sizeof distance,
                      "smallest neighbour distance %.3g of the initial spacing (stable >= %.1f, "
                      "unstable < %.1f)",
                      minDistanceRatio_, stableDistance, unstableDistance);
        char indicator[160];
        std::snprintf(indicator, sizeof indicator,
                      "largest zero-energy indicator %.3g (stable <= %.1f, unstable > %.1f)",
                      maxIndicator_, stableIndicator, unstableIndicator);
        if (!indicatorApplies_)
        {
            const char* notApplicable = "zero-energy indicator not applicable (F is the dilation "
                                        "frame of gradF elasticState, not the map from the "
                                        "initial positions)";
            const std::string word = minDistanceRatio_ < unstableDistance ? "unstable"
                                     : minDistanceRatio_ < stableDistance ? "suspect"
                                                                          : "stable";
            return {word, std::string(distance) + "; " + notApplicable};
        }
        if (minDistanceRatio_ < unstableDistance)
        {
            return {"unstable", distance};
        }
        if (maxIndicator_ > unstableIndicator)
        {
            return {"unstable", indicator};
        }
        if (minDistanceRatio_ < stableDistance)
        {
            return {"suspect", distance};
        }
        if (maxIndicator_ > stableIndicator)
        {
            return {"suspect", indicator};
        }
        return {"stable", std::string(distance) + "; " + indicator};
    }

    // The particle spacing: V0^(1/D) of the median particle.
    static double initialSpacing(const ParticleSet<D>& p)
    {
        std::vector<double> volumes = p.V0;
        std::nth_element(volumes.begin(), volumes.begin() + static_cast<long>(volumes.size() / 2),
                         volumes.end());
        return std::pow(volumes[volumes.size() / 2], 1.0 / D);
    }

    double spacing_;
    bool indicatorApplies_; // F is the total map (else the verdict is the closest pair's)
    double first_ = 0.0;
    bool haveFirst_ = false;
    double last_ = 0.0;
    double maxIndicator_ = 0.0;
    double minDistanceRatio_ = std::numeric_limits<double>::max();
    double lowestJ_ = std::numeric_limits<double>::max();
    double highestJ_ = std::numeric_limits<double>::lowest();
};

SPH_REGISTER_DIM_MODEL(FunctionObject, StabilityMonitor, "stabilityMonitor");

} // namespace sph
