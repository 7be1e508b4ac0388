#pragma once
// How a study measures each run: a runtime-selectable family, one file per type under
// metrics/, each registered in one line and listed by `sphStudy -listTypes studyMetric`.
//
//   metrics { tipError { type exactSolution; functionObject tipError; } ... }
//
// A metric is built once per study (its keys checked against its schema when studyDict is
// read) and evaluated on every run; a value that cannot be measured (a run that failed before
// writing its tables) throws, and the study records it as not available. A metric that can
// measure nothing because studyDict is wrong (a column the table does not have, a table a
// finished run did not write, time ranges that do not overlap) throws MetricDefinitionError
// instead: the study stops with it at its place in studyDict.

#include "StudyDefinition.hpp"

#include "core/InputError.hpp"
#include "core/Registry.hpp"

#include <filesystem>
#include <set>
#include <string>

namespace sph
{

// One run of a study, as a metric sees it.
struct StudyRun
{
    StudyVariant variant;
    std::filesystem::path caseDir; // the study's case folder (reference files are relative to it)
    std::filesystem::path runsDir; // postProcessing/study/runs: one folder per variant
    std::set<std::string> finished; // the variants run so far that finished (this one included)

    std::filesystem::path dir() const { return dirOf(variant.name); }
    bool hasFinished(const std::string& variantName) const
    {
        return finished.count(variantName) > 0;
    }
    std::filesystem::path dirOf(const std::string& variantName) const
    {
        return runsDir / variantName;
    }
};

// studyDict, not a run, is wrong: the study stops (finished variants are kept for the next call).
class MetricDefinitionError : public InputError
{
public:
    using InputError::InputError;
};

class StudyMetric
{
public:
    static constexpr const char* family = "studyMetric";
    static constexpr int dimension = 0;
    static constexpr bool caseLibraries = false; // compiled into sphStudy; no `libs` here
    struct Args
    {
        // The study read so far (axes and variants; valid only while the metric is built).
        const StudyDefinition& study;
        std::string name;                // the metric's name in studyDict
        std::filesystem::path caseDir;   // the study's case (reference files are relative to it)
    };

    explicit StudyMetric(const Args& args) : name_(args.name) {}
    virtual ~StudyMetric() = default;

    const std::string& name() const { return name_; }

    // The value for one run; throws when it cannot be measured.
    virtual double evaluate(const StudyRun& run) const = 0;
    // The variant that `variant` is compared with (run first), "" when the metric uses none.
    virtual std::string referenceOf(const StudyVariant&) const { return {}; }

private:
    std::string name_;
};

// A number from a run's postProcessing/summary.json by path, e.g. functions/energy/maxDrift.
double summaryValue(const StudyRun& run, const std::string& path);

} // namespace sph
