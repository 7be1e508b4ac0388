// `oscillation`: the period and amplitude of a probe's oscillation (e.g. the tip of the
// oscillating plate, spec §11.3), from the downward zero crossings of one displacement
// component: the mean period over all complete cycles, the last period, and the first and last
// cycle's amplitude (their ratio shows damping or growth).
// Keys:
//   point     | the probe, by initial position [m] (nearest particle)  | required
//   component | x, y or z                                               | y (x in 1D)
//   body      | only look in this body                                  | optional
// Columns: displacement velocity (of that component).
#include "functionObjects/FunctionObjectModel.hpp"
#include "functionObjects/PeriodTracker.hpp"

#include <cstdio>

namespace sph
{

template <int D>
class Oscillation : public FunctionObjectModel<D>
{
public:
    static std::string description()
    {
        return "Period and amplitude of a probe's oscillation, from the zero crossings of a "
               "displacement component.";
    }
    static Schema schema()
    {
        return FunctionObjectModel<D>::commonSchema()
            .add(Key::vector("point", "the probe, by initial position [m]"))
            .add(Key::word("component", "displacement component").choices({"x", "y", "z"}).optional())
            .add(Key::body("body", "only look in this body").optional());
    }

    Oscillation(const Params& params, const typename FunctionObject<D>::Args& args)
        : FunctionObjectModel<D>(params, args)
    {
        const std::string component = params.has("component") ? params.word("component") : (D == 1 ? "x" : "y");
        component_ = component == "x" ? 0 : component == "y" ? 1 : 2;
        if (component_ >= D)
        {
            params.fail("component", "oscillation: no component '" + component + "' in " + std::to_string(D) + "D");
        }
        const ParticleSet<D>& p = *args.initial;
        std::size_t begin = 0;
        std::size_t end = p.size();
        if (params.has("body"))
        {
            begin = p.bodies[params.bodyIndex("body")].begin;
            end = p.bodies[params.bodyIndex("body")].end;
        }
        const Vec<D> target = toVec<D>(params.vector("point"));
        probe_ = begin;
        for (std::size_t a = begin; a < end; ++a)
        {
            if ((p.X[a] - target).squaredNorm() < (p.X[probe_] - target).squaredNorm())
            {
                probe_ = a;
            }
        }
        this->setColumns({"displacement", "velocity"});
    }

    bool distributable() const override { return true; } // ParticleRanks

    void execute(const StepState<D>& state) override
    {
        // The probe's displacement and velocity, from the rank that owns it.
        const std::vector<double> probe =
            state.rankView().fromOwners({probe_}, 2, [&](std::size_t a, double* out) {
                out[0] = state.particles.x[a][component_] - state.particles.X[a][component_];
                out[1] = state.velocity[a][component_];
            });
        periods_.add(state.time, probe[0]);
        if (this->rowDue(state.time, state.deltaT))
        {
            this->writeRow(state.time, state.deltaT, probe);
        }
    }

    std::vector<std::string> report() const override
    {
        char line[256];
        std::snprintf(line, sizeof line,
                      "%s: %ld complete periods, mean %.6g s, last %.6g s; amplitude of the first "
                      "%.4g m, of the last %.4g m",
                      this->name().c_str(), periods_.periods(), periods_.meanPeriod(),
                      periods_.lastPeriod(), periods_.firstAmplitude(), periods_.lastAmplitude());
        return {line};
    }
    std::map<std::string, double> results() const override
    {
        return {{"periods", static_cast<double>(periods_.periods())},
                {"meanPeriod", periods_.meanPeriod()},
                {"lastPeriod", periods_.lastPeriod()},
                {"firstAmplitude", periods_.firstAmplitude()},
                {"lastAmplitude", periods_.lastAmplitude()}};
    }
    void saveState(std::map<std::string, double>& state) const override
    {
        FunctionObjectModel<D>::saveState(state);
        periods_.save(state, "periods");
    }
    void restoreState(const std::map<std::string, double>& state) override
    {
        FunctionObjectModel<D>::restoreState(state);
        periods_.restore(state, "periods");
    }

private:
    std::vector<std::string> summaryExtras() const override
    {
        return {"particle " + std::to_string(probe_)};
    }

    int component_ = 1;
    std::size_t probe_ = 0;
    PeriodTracker periods_;
};

SPH_REGISTER_DIM_MODEL(FunctionObject, Oscillation, "oscillation");

} // namespace sph
