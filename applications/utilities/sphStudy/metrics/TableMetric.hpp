#pragma once
// What the referenceVariant and referenceFile metrics share: a column of a table each run
// writes, compared with a reference column over their common time range.

#include "StudyMetric.hpp"

#include "io/DatTable.hpp"

namespace sph
{

class TableMetric : public StudyMetric
{
public:
    // file, column, norm, scale.
    static Schema tableSchema();
    TableMetric(const Params& p, const Args& args);

protected:
    // What a run is compared with.
    struct Reference
    {
        const DatTable& table;
        std::string column;
        std::string description; // "the reference table 'ref.dat'", "run n40_TLnone"
        bool complete;           // a fixed table, or a reference run that finished
    };

    // max or rms of (the run's column - the reference column interpolated at the run's times)
    // over their common time range, or the absolute value of its mean (norm mean), relative to `scale`, or to max |reference| without one.
    // MetricDefinitionError when studyDict is wrong (no common time between a finished run and
    // a complete reference, a reference of zeros without `scale`), std::runtime_error when a
    // run did not produce what is compared (not available).
    double compare(const StudyRun& run, const Reference& reference) const;
    // The table `file` of a run, with a column `column`: MetricDefinitionError at those keys
    // when a finished run did not write it or it lacks the column, std::runtime_error when the
    // run did not finish and wrote no table.
    DatTable runTable(const StudyRun& run, const std::string& variant) const;

    std::string file_;   // relative to each run's folder
    std::string column_;
    SourceLocation metricAt_; // the metric's dictionary in studyDict

private:
    std::string norm_;   // max | rms | mean
    double scale_ = 0.0; // > 0: divide by this instead
    SourceLocation fileAt_;
    SourceLocation columnAt_;
};

} // namespace sph
