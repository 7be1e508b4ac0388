#include "metrics/TableMetric.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sph
{

Schema TableMetric::tableSchema()
{
    return Schema()
        .add(Key::string("file", "a table each run writes, relative to its case, e.g. "
                                 "postProcessing/extent/extent.dat"))
        .add(Key::word("column", "the column of that table"))
        .add(Key::word("norm", "max or rms of the difference over the common time range")
                 .choices({"max", "rms"})
                 .defaultValue("max"))
        .add(Key::real("scale", "divide the difference by this instead of max |reference|")
                 .positive()
                 .optional());
}

TableMetric::TableMetric(const Params& p, const Args& args)
    : StudyMetric(args), file_(p.string("file")), column_(p.word("column")),
      norm_(p.word("norm")), scale_(p.has("scale") ? p.real("scale") : 0.0)
{
}

double TableMetric::compare(const StudyRun& run, const DatTable& referenceTable,
                            const std::string& referenceColumn) const
{
    const DatTable own = readDatTable(run.dir() / file_);
    const std::vector<double> time = own.columnAt(0);
    const std::vector<double> value = own.column(column_);
    const std::vector<double> referenceTime = referenceTable.columnAt(0);
    const std::vector<double> reference = referenceTable.column(referenceColumn);
    double scale = scale_;
    if (scale <= 0.0)
    {
        for (double r : reference)
        {
            scale = std::max(scale, std::abs(r));
        }
    }
    double worst = 0.0;
    double squares = 0.0;
    std::size_t count = 0;
    std::size_t j = 0;
    for (std::size_t i = 0; i < time.size() && i < value.size(); ++i)
    {
        const double t = time[i];
        if (referenceTime.empty() || t < referenceTime.front() || t > referenceTime.back())
        {
            continue;
        }
        while (j + 1 < referenceTime.size() && referenceTime[j + 1] < t)
        {
            ++j;
        }
        double r = reference[j];
        if (j + 1 < referenceTime.size() && referenceTime[j + 1] > referenceTime[j])
        {
            const double s = (t - referenceTime[j]) / (referenceTime[j + 1] - referenceTime[j]);
            r = (1.0 - s) * reference[j] + s * reference[j + 1];
        }
        const double d = std::abs(value[i] - r);
        worst = std::max(worst, d);
        squares += d * d;
        ++count;
    }
    if (count == 0 || scale == 0.0)
    {
        return std::numeric_limits<double>::quiet_NaN();
    }
    return (norm_ == "rms" ? std::sqrt(squares / static_cast<double>(count)) : worst) / scale;
}

} // namespace sph
