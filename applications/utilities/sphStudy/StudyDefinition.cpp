#include "StudyDefinition.hpp"
#include "StudyMetric.hpp"

#include "core/CommandLine.hpp"
#include "core/InputError.hpp"
#include "core/PlainName.hpp"
#include "core/Schema.hpp"
#include "core/Suggest.hpp"

#include <algorithm>
#include <cctype>

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
                 .range(0, static_cast<double>(maxThreads))
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
                 .defaultValue("yes"))
        .add(Key::string("baseCase", "the case each variant copies (its system/ and constant/), "
                                     "relative to this one, e.g. \"../dykaBar\" (default: this "
                                     "case)")
                 .optional());
}

Schema levelSchema()
{
    return Schema()
        .add(Key::stringList("particles", "overrides for sphParticles, e.g. (\"bar.n=80\")")
                 .defaultValue("()"))
        .add(Key::stringList("solver", "overrides for sphSolid, e.g. (\"courant=0.1\")")
                 .defaultValue("()"));
}

Schema restrictedLevelSchema()
{
    return levelSchema().add(
        Key::dict("only", "{ axis (level ...); ... }: combine this level only with these levels "
                          "of other axes (default: with every level)")
            .optional());
}

// A level's `only { axis (level ...); ... }`: the levels of the other axes it is combined with.
std::map<std::string, std::vector<std::string>>
readOnly(const Dictionary& only, const std::vector<StudyAxis>& axes, const std::string& ownAxis)
{
    std::vector<std::string> axisNames;
    for (const auto& axis : axes)
    {
        if (axis.name != ownAxis)
        {
            axisNames.push_back(axis.name);
        }
    }
    std::map<std::string, std::vector<std::string>> result;
    for (const Entry& entry : only.entries())
    {
        const auto axis = std::find_if(axes.begin(), axes.end(),
                                       [&](const StudyAxis& a) { return a.name == entry.key(); });
        if (axis == axes.end() || axis->name == ownAxis)
        {
            throw InputError(entry.keyLocation(),
                             axis == axes.end()
                                 ? "only: no axis '" + entry.key() + "'"
                                 : "only: '" + ownAxis + "' is this level's own axis",
                             {"Other axes: " + joinSorted(axisNames),
                              didYouMean(entry.key(), axisNames)});
        }
        const std::vector<Item>& value =
            entry.items().size() == 1 && entry.items()[0].isList() ? entry.items()[0].items()
                                                                   : entry.items();
        if (entry.isDict() || value.empty())
        {
            throw InputError(entry.keyLocation(),
                             "only: '" + entry.key() + "' needs the levels it may be combined with",
                             {"e.g. only { " + entry.key() + " (" + axis->levels.front().name +
                              "); }"});
        }
        std::vector<std::string> levelNames;
        for (const auto& level : axis->levels)
        {
            levelNames.push_back(level.name);
        }
        for (const Item& item : value)
        {
            if (item.kind() == Item::Kind::List ||
                std::find(levelNames.begin(), levelNames.end(), item.text()) == levelNames.end())
            {
                throw InputError(item.location(),
                                 "only: axis '" + entry.key() + "' has no level " +
                                     (item.isList() ? item.describe() : "'" + item.text() + "'"),
                                 {"Levels: " + joinSorted(levelNames),
                                  didYouMean(item.text(), levelNames)});
            }
            result[entry.key()].push_back(item.text());
        }
    }
    return result;
}

// The `only` of every level (they may name axes defined after their own), then a check that
// every level is still in some variant.
void readRestrictions(const Dictionary& axesDict, StudyDefinition& study)
{
    std::size_t a = 0;
    for (const Entry& axisEntry : axesDict.entries())
    {
        std::size_t l = 0;
        for (const Entry& levelEntry : axisEntry.dict().entries())
        {
            if (const Entry* only = levelEntry.dict().find("only"); only && only->isDict())
            {
                study.axes[a].levels[l].only = readOnly(only->dict(), study.axes, axisEntry.key());
            }
            ++l;
        }
        ++a;
    }
    const auto variants = study.variants();
    a = 0;
    for (const Entry& axisEntry : axesDict.entries())
    {
        for (const Entry& levelEntry : axisEntry.dict().entries())
        {
            if (std::none_of(variants.begin(), variants.end(), [&](const StudyVariant& v)
                             { return v.levels[a] == levelEntry.key(); }))
            {
                throw InputError(levelEntry.keyLocation(),
                                 "level '" + levelEntry.key() + "' of axis '" + axisEntry.key() +
                                     "' is in no variant",
                                 {"The 'only' lists of the levels leave no combination with it."});
            }
        }
        ++a;
    }
}

// Axis, level and metric names become folder and file names (runs/<variant>, plot/<line>.dat)
// and text in the generated gnuplot script.
void checkPlainName(const Entry& entry, const std::string& what)
{
    requirePlainName(entry, what, "folder, file and plot names");
}

} // namespace

StudyDefinition StudyDefinition::read(const Dictionary& studyDict,
                                      const std::filesystem::path& caseDir)
{
    const Params p = studySchema().validate(studyDict, "studyDict");
    StudyDefinition study;
    study.baseCase = caseDir;
    if (p.has("baseCase"))
    {
        study.baseCase = (caseDir / p.string("baseCase")).lexically_normal();
        if (!std::filesystem::is_directory(study.baseCase / "system") ||
            !std::filesystem::is_directory(study.baseCase / "constant"))
        {
            p.fail("baseCase", "no case at '" + study.baseCase.string() + "'",
                   {"baseCase names a case folder (with system/ and constant/), relative to the "
                    "study's folder, e.g. \"../dykaBar\"."});
        }
    }
    if (p.has("common"))
    {
        const Params q = levelSchema().validate(p.dict("common"), "common");
        study.common = {"common", q.stringList("particles"), q.stringList("solver"), {}};
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
        checkPlainName(axisEntry, "axis");
        StudyAxis axis{axisEntry.key(), {}};
        for (const Entry& levelEntry : axisEntry.dict().entries())
        {
            checkPlainName(levelEntry, "level");
            if (!levelEntry.isDict())
            {
                throw InputError(levelEntry.keyLocation(),
                                 "level '" + levelEntry.key() + "' of axis '" + axis.name +
                                     "' must be a dictionary { particles (...); solver (...); }");
            }
            const Params q =
                restrictedLevelSchema().validate(levelEntry.dict(), "a study level");
            axis.levels.push_back(
                {levelEntry.key(), q.stringList("particles"), q.stringList("solver"), {}});
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
    readRestrictions(p.dict("axes"), study);
    for (const Entry& entry : p.dict("metrics").entries())
    {
        checkPlainName(entry, "metric");
        if (!entry.isDict())
        {
            throw InputError(entry.keyLocation(),
                             "metric '" + entry.key() + "' must be a dictionary { type ...; }",
                             {"Metric types: " +
                              joinSorted(Registry<StudyMetric>::names()) +
                              " (sphStudy -listTypes studyMetric)"});
        }
        study.metrics.push_back(
            selectModel<StudyMetric>(entry.dict(), {study, entry.key(), caseDir}, 0));
    }
    if (study.metrics.empty())
    {
        throw InputError(p.location("metrics"), "studyDict: 'metrics' defines no metric");
    }
    // A reference variant that `only` leaves out could never be measured against.
    std::vector<std::string> variantNames;
    for (const auto& variant : study.variants())
    {
        variantNames.push_back(variant.name);
    }
    for (const auto& metric : study.metrics)
    {
        for (const auto& variant : study.variants())
        {
            const std::string reference = metric->referenceOf(variant);
            if (!reference.empty() && std::find(variantNames.begin(), variantNames.end(),
                                                reference) == variantNames.end())
            {
                throw InputError(p.dict("metrics").find(metric->name())->keyLocation(),
                                 "metric '" + metric->name() + "' compares " + variant.name +
                                     " with " + reference + ", which is not a variant",
                                 {"The 'only' lists of the levels leave " + reference +
                                  " out of the study; compare with a variant that is in it."});
            }
        }
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

} // namespace sph
