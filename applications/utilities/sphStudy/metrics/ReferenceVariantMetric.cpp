// `referenceVariant`: a column of each run's table against the same column of another variant
// of the study: one named variant, or the one that differs only in given levels.
#include "metrics/TableMetric.hpp"

#include "core/Suggest.hpp"

#include <algorithm>
#include <map>

namespace sph
{

class ReferenceVariantMetric : public TableMetric
{
public:
    static std::string description()
    {
        return "A column of a table each run writes against the same column of a reference "
               "variant of the study, which runs first: 'variant' (one for all), or "
               "'referenceLevels' { axis level; } (each variant against the one that differs "
               "only in these levels, e.g. the same scheme at the finest resolution).";
    }
    static Schema schema()
    {
        return tableSchema()
            .add(Key::word("variant", "the variant every run is compared with (or "
                                      "referenceLevels)")
                     .optional())
            .add(Key::dict("referenceLevels", "{ axis level; ... }: compare each variant with "
                                              "the one that differs only in these levels")
                     .optional());
    }
    ReferenceVariantMetric(const Params& p, const Args& args) : TableMetric(p, args)
    {
        if (p.has("variant") == p.has("referenceLevels"))
        {
            throw InputError(p.source().location(),
                             "metric '" + name() +
                                 "' of type referenceVariant needs either 'variant' or "
                                 "'referenceLevels'",
                             {"variant NAME; compares every variant with one; referenceLevels "
                              "{ axis level; } with the variant that differs only there."});
        }
        for (const auto& axis : args.study.axes)
        {
            axes_.push_back(axis.name);
        }
        if (p.has("variant"))
        {
            readVariant(p, args.study);
        }
        else
        {
            readLevels(p.dict("referenceLevels"), args.study);
        }
    }

    double evaluate(const StudyRun& run) const override
    {
        const std::string reference = referenceOf(run.variant);
        return compare(run, {runTable(run, reference), column_, "the run " + reference,
                             run.hasFinished(reference)});
    }

    std::string referenceOf(const StudyVariant& variant) const override
    {
        if (!variant_.empty())
        {
            return variant_;
        }
        std::string name;
        for (std::size_t a = 0; a < axes_.size(); ++a)
        {
            const auto level = levels_.find(axes_[a]);
            name += (a ? "_" : "") + (level != levels_.end() ? level->second : variant.levels[a]);
        }
        return name;
    }

private:
    void readVariant(const Params& p, const StudyDefinition& study)
    {
        variant_ = p.word("variant");
        std::vector<std::string> names;
        for (const auto& variant : study.variants())
        {
            names.push_back(variant.name);
        }
        if (std::find(names.begin(), names.end(), variant_) == names.end())
        {
            p.fail("variant", "metric '" + name() + "': no variant '" + variant_ + "'",
                   {"Variants are the level names joined by '_' in axis order, e.g. " +
                        names.front() + ".",
                    didYouMean(variant_, names)});
        }
    }

    void readLevels(const Dictionary& levels, const StudyDefinition& study)
    {
        for (const Entry& entry : levels.entries())
        {
            const auto axis =
                std::find_if(study.axes.begin(), study.axes.end(),
                             [&](const StudyAxis& a) { return a.name == entry.key(); });
            if (axis == study.axes.end())
            {
                throw InputError(entry.keyLocation(),
                                 "referenceLevels: no axis '" + entry.key() + "'",
                                 {"Axes: " + joinSorted(axes_), didYouMean(entry.key(), axes_)});
            }
            const std::string level =
                entry.isDict() || entry.items().size() != 1 ? "" : entry.items()[0].text();
            std::vector<std::string> names;
            for (const auto& l : axis->levels)
            {
                names.push_back(l.name);
            }
            if (std::find(names.begin(), names.end(), level) == names.end())
            {
                throw InputError(entry.isDict() ? entry.keyLocation() : entry.valueLocation(),
                                 "referenceLevels: axis '" + entry.key() + "' has no level '" +
                                     level + "'",
                                 {"Levels: " + joinSorted(names), didYouMean(level, names)});
            }
            levels_[entry.key()] = level;
        }
    }

    std::string variant_;                       // one reference for all, or
    std::vector<std::string> axes_;             // the axes in order, and
    std::map<std::string, std::string> levels_; // axis -> the reference's level there
};

SPH_REGISTER_MODEL(StudyMetric, ReferenceVariantMetric, "referenceVariant");

} // namespace sph
