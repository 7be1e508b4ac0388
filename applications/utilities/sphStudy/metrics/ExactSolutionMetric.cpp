// `exactSolution`: the error an exactSolution function object of the case reports in each
// run's summary.json (functions/<functionObject>/<value>).
#include "StudyMetric.hpp"

namespace sph
{

class ExactSolutionMetric : public StudyMetric
{
public:
    static std::string description()
    {
        return "An error against an analytic solution: the result 'value' of the case's "
               "exactSolution function object 'functionObject', as each run's summary.json "
               "reports it (e.g. the relative L-inf error of the Dyka bar's free end).";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::word("functionObject", "the exactSolution function object's name"))
            .add(Key::string("value", "its result in summary.json, e.g. relativeRmsError, "
                                      "relativeMaxPeriodMean")
                     .defaultValue("relativeLinfError"));
    }
    ExactSolutionMetric(const Params& p, const Args& args)
        : StudyMetric(args),
          path_("functions/" + p.word("functionObject") + "/" + p.string("value"))
    {
    }
    double evaluate(const StudyRun& run) const override { return summaryValue(run, path_); }

private:
    std::string path_;
};

SPH_REGISTER_MODEL(StudyMetric, ExactSolutionMetric, "exactSolution");

} // namespace sph
