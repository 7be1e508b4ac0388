// `summary`: any number of each run's postProcessing/summary.json.
#include "StudyMetric.hpp"

namespace sph
{

class SummaryMetric : public StudyMetric
{
public:
    static std::string description()
    {
        return "Any number of each run's postProcessing/summary.json, by its path: "
               "functions/energy/maxDrift, functions/stability/minDistanceRatio, time (the "
               "time reached), ...";
    }
    static Schema schema()
    {
        return Schema().add(
            Key::string("value", "a path in summary.json, e.g. functions/energy/maxDrift"));
    }
    SummaryMetric(const Params& p, const Args& args) : StudyMetric(args), path_(p.string("value"))
    {
    }
    double evaluate(const StudyRun& run) const override { return summaryValue(run, path_); }

private:
    std::string path_;
};

SPH_REGISTER_MODEL(StudyMetric, SummaryMetric, "summary");

} // namespace sph
