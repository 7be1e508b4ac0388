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
    // max or rms of (the run's column - the reference column interpolated at the run's times)
    // over their common time range, relative to `scale`, or to max |reference| without one.
    double compare(const StudyRun& run, const DatTable& reference,
                   const std::string& referenceColumn) const;

    std::string file_;   // relative to each run's folder
    std::string column_;

private:
    std::string norm_;   // max | rms
    double scale_ = 0.0; // > 0: divide by this instead
};

} // namespace sph
