// `referenceFile`: a column of each run's table against a column of a fixed table (measured
// data, a converged run kept from earlier, ...).
#include "metrics/TableMetric.hpp"

#include "core/CaseFile.hpp"

namespace sph
{

class ReferenceFileMetric : public TableMetric
{
public:
    static std::string description()
    {
        return "A column of a table each run writes against a column of a reference table "
               "(e.g. measured data): 'reference', relative to the study's case, first column "
               "time; its header line of column names may be left out, its columns are then "
               "numbered from 1.";
    }
    static Schema schema()
    {
        return tableSchema()
            .add(Key::string("reference", "the reference table, relative to the case"))
            .add(Key::string("referenceColumn", "its column: a name, or a 1-based number in "
                                                "quotes (\"2\")"));
    }
    // The reference is read, and its column checked, when studyDict is read: before any run.
    ReferenceFileMetric(const Params& p, const Args& args)
        : TableMetric(p, args),
          reference_(readDatTable(caseFile(p, "reference", args.caseDir, "the reference table",
                                           "The reference is a table of the study's case: "
                                           "time in the first column, e.g. "
                                           "\"constant/measured.dat\"."),
                                  DatHeader::optional)),
          referenceColumn_(p.string("referenceColumn")),
          description_("the reference table '" + p.string("reference") + "'")
    {
        if (reference_.rows.empty())
        {
            p.fail("reference", "metric '" + name() + "': " + description_ + " has no rows",
                   {"Rows of numbers, time first, one per line; a line starting with '#' is a "
                    "comment (the first one may name the columns)."});
        }
        try
        {
            reference_.columnIndex(referenceColumn_);
        }
        catch (const InputError& noColumn)
        {
            std::vector<std::string> notes = noColumn.notes();
            notes.push_back("A column is named in the table's first line ('# time a b'), or "
                            "numbered from 1 in quotes (\"2\") when the table has no such line.");
            p.fail("referenceColumn",
                   "metric '" + name() + "': " + description_ + " has no column '" +
                       referenceColumn_ + "'",
                   notes);
        }
    }

    double evaluate(const StudyRun& run) const override
    {
        return compare(run, {reference_, referenceColumn_, description_, true});
    }

private:
    DatTable reference_;
    std::string referenceColumn_;
    std::string description_;
};

SPH_REGISTER_MODEL(StudyMetric, ReferenceFileMetric, "referenceFile");

} // namespace sph
