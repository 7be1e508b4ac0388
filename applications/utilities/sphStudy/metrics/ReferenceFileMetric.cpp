// `referenceFile`: a column of each run's table against a column of a fixed table (measured
// data, a converged run kept from earlier, ...).
#include "metrics/TableMetric.hpp"

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
    ReferenceFileMetric(const Params& p, const Args& args)
        : TableMetric(p, args), reference_(p.string("reference")),
          referenceColumn_(p.string("referenceColumn"))
    {
    }

    double evaluate(const StudyRun& run) const override
    {
        return compare(run, readDatTable(run.caseDir / reference_, DatHeader::optional),
                       referenceColumn_);
    }

private:
    std::string reference_;
    std::string referenceColumn_;
};

SPH_REGISTER_MODEL(StudyMetric, ReferenceFileMetric, "referenceFile");

} // namespace sph
