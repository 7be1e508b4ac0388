// `summary`: any number of each run's postProcessing/summary.json, optionally shifted by a
// number of the run's particle spacings and turned into a relative error against a reference.
#include "StudyMetric.hpp"

#include <cmath>

namespace sph
{

class SummaryMetric : public StudyMetric
{
public:
    static std::string description()
    {
        return "Any number of each run's postProcessing/summary.json, by its path: "
               "functions/energy/maxDrift, functions/stability/minDistanceRatio, time (the "
               "time reached), ...; with `plusSpacings n` the run's particle spacing times n "
               "is added (an extent of particle centres made a body's: 0.5), and with "
               "`reference r` the metric is the relative error |value - r| / |r|";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::string("value", "a path in summary.json, e.g. functions/energy/maxDrift"))
            .add(Key::real("plusSpacings", "the run's particle spacing (summary.json's spacing) "
                                           "times this is added to the value: 0.5 turns the "
                                           "extent of the particles' centres into the body's")
                     .defaultValue("0"))
            .add(Key::real("reference", "report |value - reference| / |reference| instead of "
                                        "the value (the error against a measured or converged "
                                        "figure, in the value's units)")
                     .optional());
    }
    SummaryMetric(const Params& p, const Args& args)
        : StudyMetric(args), path_(p.string("value")), plusSpacings_(p.real("plusSpacings"))
    {
        if (p.has("reference"))
        {
            reference_ = p.real("reference");
            if (!(reference_ != 0.0) || !std::isfinite(reference_))
            {
                p.fail("reference", "the reference must be a finite number other than 0 (the "
                                    "error is relative to it)",
                       {"hint: leave `reference` out to report the value itself"});
            }
        }
    }
    double evaluate(const StudyRun& run) const override
    {
        double value = summaryValue(run, path_);
        if (plusSpacings_ != 0.0)
        {
            value += plusSpacings_ * summaryValue(run, "spacing");
        }
        return std::isnan(reference_) ? value : std::abs(value - reference_) / std::abs(reference_);
    }

private:
    std::string path_;
    double plusSpacings_;
    double reference_ = std::nan("");
};

SPH_REGISTER_MODEL(StudyMetric, SummaryMetric, "summary");

} // namespace sph
