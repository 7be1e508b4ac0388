// The variants of a study: every combination of the axes' levels that the levels' `only`
// restrictions allow, references first.
#include "StudyDefinition.hpp"

#include "StudyMetric.hpp"

#include <algorithm>

namespace sph
{

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

bool StudyDefinition::nextCombination(std::vector<std::size_t>& index) const
{
    for (std::size_t a = axes.size(); a-- > 0;)
    {
        if (++index[a] < axes[a].levels.size())
        {
            return true;
        }
        index[a] = 0;
    }
    return false;
}

bool StudyDefinition::allowed(const std::vector<std::size_t>& index) const
{
    for (std::size_t a = 0; a < axes.size(); ++a)
    {
        for (const auto& [axis, levels] : axes[a].levels[index[a]].only)
        {
            const std::size_t b = axisIndex(axis);
            if (std::find(levels.begin(), levels.end(), axes[b].levels[index[b]].name) ==
                levels.end())
            {
                return false;
            }
        }
    }
    return true;
}

std::vector<StudyVariant> StudyDefinition::variants() const
{
    std::vector<StudyVariant> result;
    std::vector<std::size_t> index(axes.size(), 0); // an odometer over the levels
    bool done = false;
    for (; !done; done = !nextCombination(index))
    {
        if (!allowed(index))
        {
            continue;
        }
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
