#include "StudyDefinition.hpp"
#include "StudyMetric.hpp"

#include "core/InputError.hpp"
#include "core/Schema.hpp"
#include "core/Suggest.hpp"

#include <algorithm>

namespace sph
{

namespace
{

Schema studySchema()
{
    return Schema()
        .add(Key::dict("axes", "what the study varies: axis { level { particles (...); solver "
                               "(...); } ... }"))
        .add(Key::dict("common",
                       "overrides every variant shares: { particles (...); solver (...); }")
                 .optional())
        .add(Key::integer("repeats", "runs per variant; the times are their median")
                 .min(1)
                 .defaultValue("1"))
        .add(Key::integer("threads", "OpenMP threads per run (0: all cores)")
                 .min(0)
                 .defaultValue("0"))
        .add(Key::dict("metrics", "what each run is measured by: name { type exactSolution | "
                                  "summary | referenceVariant | referenceFile; ... } (sphStudy "
                                  "-listTypes studyMetric); the first is plotted"))
        .add(Key::dict("plot", "{ groupBy AXIS; along AXIS; }: one line per level of groupBy, "
                               "connecting the levels of along")
                 .optional())
        .add(Key::dict("stable", "{ METRIC { min X; max Y; } ... }: a finished run is stable "
                                 "when every bound holds (the report's verdict column)")
                 .optional())
        .add(Key::boolean("rank", "list the variants with the best first metric for their "
                                  "wall time (no for stability studies)")
                 .defaultValue("yes"));
}

Schema levelSchema()
{
    return Schema()
        .add(Key::stringList("particles", "overrides for sphParticles, e.g. (\"bar.n=80\")")
                 .defaultValue("()"))
        .add(Key::stringList("solver", "overrides for sphSolid, e.g. (\"courant=0.1\")")
                 .defaultValue("()"));
}

} // namespace

StudyDefinition StudyDefinition::read(const Dictionary& studyDict)
{
    const Params p = studySchema().validate(studyDict, "studyDict");
    StudyDefinition study;
    if (p.has("common"))
    {
        const Params q = levelSchema().validate(p.dict("common"), "common");
        study.common = {"common", q.stringList("particles"), q.stringList("solver")};
    }
    study.repeats = p.integer("repeats");
    study.threads = p.integer("threads");
    for (const Entry& axisEntry : p.dict("axes").entries())
    {
        if (!axisEntry.isDict())
        {
            throw InputError(axisEntry.keyLocation(),
                             "axis '" + axisEntry.key() + "' must be a dictionary of levels",
                             {"e.g. resolution { n40 { particles (\"bar.n=40\"); } }"});
        }
        StudyAxis axis{axisEntry.key(), {}};
        for (const Entry& levelEntry : axisEntry.dict().entries())
        {
            if (!levelEntry.isDict())
            {
                throw InputError(levelEntry.keyLocation(),
                                 "level '" + levelEntry.key() + "' of axis '" + axis.name +
                                     "' must be a dictionary { particles (...); solver (...); }");
            }
            const Params q = levelSchema().validate(levelEntry.dict(), "a study level");
            axis.levels.push_back(
                {levelEntry.key(), q.stringList("particles"), q.stringList("solver")});
        }
        if (axis.levels.empty())
        {
            throw InputError(axisEntry.keyLocation(), "axis '" + axis.name + "' has no level");
        }
        study.axes.push_back(axis);
    }
    if (study.axes.empty())
    {
        throw InputError(p.location("axes"), "studyDict: 'axes' defines no axis");
    }
    for (const Entry& entry : p.dict("metrics").entries())
    {
        if (!entry.isDict())
        {
            throw InputError(entry.keyLocation(),
                             "metric '" + entry.key() + "' must be a dictionary { type ...; }",
                             {"Metric types: " +
                              joinSorted(Registry<StudyMetric>::names()) +
                              " (sphStudy -listTypes studyMetric)"});
        }
        study.metrics.push_back(
            selectModel<StudyMetric>(entry.dict(), {study, entry.key()}, 0));
    }
    if (study.metrics.empty())
    {
        throw InputError(p.location("metrics"), "studyDict: 'metrics' defines no metric");
    }
    std::vector<std::string> axisNames;
    for (const auto& axis : study.axes)
    {
        axisNames.push_back(axis.name);
    }
    study.groupBy = study.axes.back().name;
    study.along = study.axes.front().name;
    if (p.has("plot"))
    {
        const Params q =
            Schema()
                .add(Key::word("groupBy", "one line per level of this axis").choices(axisNames).optional())
                .add(Key::word("along", "the lines connect the levels of this axis").choices(axisNames).optional())
                .validate(p.dict("plot"), "plot");
        if (q.has("groupBy"))
        {
            study.groupBy = q.word("groupBy");
        }
        if (q.has("along"))
        {
            study.along = q.word("along");
        }
    }
    study.rank = p.boolean("rank");
    if (p.has("stable"))
    {
        std::vector<std::string> metricNames;
        for (const auto& metric : study.metrics)
        {
            metricNames.push_back(metric->name());
        }
        for (const Entry& entry : p.dict("stable").entries())
        {
            if (std::find(metricNames.begin(), metricNames.end(), entry.key()) ==
                metricNames.end())
            {
                throw InputError(entry.keyLocation(),
                                 "stable: '" + entry.key() + "' must be one of the metrics",
                                 {"valid metrics: " + joinSorted(metricNames),
                                  didYouMean(entry.key(), metricNames)});
            }
            if (!entry.isDict())
            {
                throw InputError(entry.keyLocation(),
                                 "stable: the bounds of '" + entry.key() +
                                     "' must be a dictionary { min X; max Y; }",
                                 {"e.g. " + entry.key() + " { max 0.1; }"});
            }
            const Params q = Schema()
                                 .add(Key::real("min", "lowest stable value").optional())
                                 .add(Key::real("max", "highest stable value").optional())
                                 .validate(entry.dict(), "a stability bound");
            if (!q.has("min") && !q.has("max"))
            {
                throw InputError(entry.keyLocation(),
                                 "stable: '" + entry.key() + "' needs 'min', 'max' or both");
            }
            StabilityBound bound;
            bound.metric = entry.key();
            if (q.has("min"))
            {
                bound.min = q.real("min");
            }
            if (q.has("max"))
            {
                bound.max = q.real("max");
            }
            study.stable.push_back(bound);
        }
    }
    return study;
}

std::size_t StudyDefinition::axisIndex(const std::string& name) const
{
    for (std::size_t i = 0; i < axes.size(); ++i)
    {
        if (axes[i].name == name)
        {
            return i;
        }
    }
    return 0;
}

std::vector<StudyVariant> StudyDefinition::variants() const
{
    std::vector<StudyVariant> result;
    std::vector<std::size_t> index(axes.size(), 0); // an odometer over the levels
    bool done = false;
    while (!done)
    {
        StudyVariant variant;
        variant.particles = common.particles;
        variant.solver = common.solver;
        for (std::size_t a = 0; a < axes.size(); ++a)
        {
            const StudyLevel& level = axes[a].levels[index[a]];
            variant.name += (a ? "_" : "") + level.name;
            variant.levels.push_back(level.name);
            variant.particles.insert(variant.particles.end(), level.particles.begin(),
                                     level.particles.end());
            variant.solver.insert(variant.solver.end(), level.solver.begin(), level.solver.end());
        }
        result.push_back(variant);
        done = true;
        for (std::size_t a = axes.size(); a-- > 0;)
        {
            if (++index[a] < axes[a].levels.size())
            {
                done = false;
                break;
            }
            index[a] = 0;
        }
    }
    // Variants that others are compared with run first.
    std::stable_partition(result.begin(), result.end(),
                          [&](const StudyVariant& v)
                          {
                              return std::any_of(metrics.begin(), metrics.end(),
                                                 [&](const auto& m)
                                                 { return m->referenceOf(v) == v.name; });
                          });
    return result;
}

} // namespace sph
