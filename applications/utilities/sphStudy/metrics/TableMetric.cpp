#include "metrics/TableMetric.hpp"

#include "core/Format.hpp"
#include "core/Suggest.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sph
{

namespace
{

const char* keptForNextCall =
    "Finished variants are kept: after correcting studyDict, run sphStudy again.";

// The tables a run wrote (postProcessing/<name>/<name>.dat ...), relative to its folder.
std::vector<std::string> tablesOf(const std::filesystem::path& runDir)
{
    std::error_code ec;
    std::vector<std::string> tables;
    for (std::filesystem::recursive_directory_iterator it(runDir / "postProcessing", ec), end;
         !ec && it != end && tables.size() < 50; it.increment(ec))
    {
        if (it->path().extension() == ".dat" && it->is_regular_file(ec))
        {
            tables.push_back(it->path().lexically_relative(runDir).generic_string());
        }
    }
    return tables;
}

std::string timeRange(const std::vector<double>& time)
{
    return time.empty() ? std::string("no rows")
                        : "t = " + formatNumber(time.front()) + " to " +
                              formatNumber(time.back()) + " s (" + std::to_string(time.size()) +
                              " rows)";
}

} // namespace

Schema TableMetric::tableSchema()
{
    return Schema()
        .add(Key::string("file", "a table each run writes, relative to its case, e.g. "
                                 "postProcessing/extent/extent.dat"))
        .add(Key::word("column", "the column of that table"))
        .add(Key::word("norm", "max or rms of the difference over the common time range, or "
                               "mean: the absolute value of its mean (a plateau's offset, "
                               "the oscillation about it averaged out)")
                 .choices({"max", "rms", "mean"})
                 .defaultValue("max"))
        .add(Key::real("scale", "divide the difference by this instead of max |reference|")
                 .positive()
                 .optional());
}

TableMetric::TableMetric(const Params& p, const Args& args)
    : StudyMetric(args), file_(p.string("file")), column_(p.word("column")),
      metricAt_(p.source().location()), norm_(p.word("norm")),
      scale_(p.has("scale") ? p.real("scale") : 0.0), fileAt_(p.location("file")),
      columnAt_(p.location("column"))
{
}

DatTable TableMetric::runTable(const StudyRun& run, const std::string& variant) const
{
    const std::filesystem::path path = run.dirOf(variant) / file_;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
    {
        if (!run.hasFinished(variant))
        {
            throw std::runtime_error(path.string() + ": not written (the run did not finish)");
        }
        const std::vector<std::string> tables = tablesOf(run.dirOf(variant));
        throw MetricDefinitionError(
            fileAt_,
            "metric '" + name() + "': the run " + variant + " finished without writing '" +
                file_ + "'",
            {"Tables it wrote: " + (tables.empty() ? std::string("none") : joinSorted(tables)),
             didYouMean(file_, tables),
             "'file' is relative to each run's case folder; the function object that writes "
             "it must be in the case's controlDict.",
             keptForNextCall});
    }
    DatTable table = readDatTable(path); // a damaged table: not available
    try
    {
        table.columnIndex(column_);
    }
    catch (const InputError& noColumn)
    {
        std::vector<std::string> notes = noColumn.notes();
        notes.push_back(keptForNextCall);
        throw MetricDefinitionError(columnAt_,
                                    "metric '" + name() + "': the table '" + file_ +
                                        "' of the run " + variant + " has no column '" +
                                        column_ + "'",
                                    notes);
    }
    return table;
}

double TableMetric::compare(const StudyRun& run, const Reference& referenceRun) const
{
    const DatTable own = runTable(run, run.variant.name);
    const std::vector<double> time = own.columnAt(0);
    const std::vector<double> value = own.column(column_);
    const std::vector<double> referenceTime = referenceRun.table.columnAt(0);
    const std::vector<double> reference = referenceRun.table.column(referenceRun.column);
    // A finished run against a complete reference measures something, or studyDict is wrong.
    const bool mustMeasure = run.hasFinished(run.variant.name) && referenceRun.complete;
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
    double sum = 0.0;
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
        sum += value[i] - r;
        const double d = std::abs(value[i] - r);
        worst = std::max(worst, d);
        squares += d * d;
        ++count;
    }
    if (count == 0)
    {
        const std::string message = "metric '" + name() + "': the run " + run.variant.name +
                                    " and " + referenceRun.description +
                                    " have no time in common: the run's '" + file_ +
                                    "' has " + timeRange(time) + ", the reference " +
                                    timeRange(referenceTime);
        if (!mustMeasure)
        {
            throw std::runtime_error(message);
        }
        throw MetricDefinitionError(
            metricAt_, message,
            {"The first column of both tables is the time in seconds: is the reference in "
             "other units (ms?), or does it start after the runs' endTime?",
             keptForNextCall});
    }
    if (scale == 0.0)
    {
        const std::string message = "metric '" + name() + "': the column '" +
                                    referenceRun.column + "' of " + referenceRun.description +
                                    " is zero everywhere: a difference relative to it is not "
                                    "defined";
        if (!mustMeasure)
        {
            throw std::runtime_error(message);
        }
        throw MetricDefinitionError(metricAt_, message,
                                    {"Give the metric a 'scale' to divide by instead, e.g. "
                                     "scale 1e-3; for differences in mm.",
                                     keptForNextCall});
    }
    const double n = static_cast<double>(count);
    if (norm_ == "mean")
    {
        return std::abs(sum / n) / scale;
    }
    return (norm_ == "rms" ? std::sqrt(squares / n) : worst) / scale;
}

} // namespace sph
