#pragma once
// Small statistics of measured samples (wall times of repeated runs, ...).

#include <algorithm>
#include <limits>
#include <vector>

namespace sph
{

// The median: the middle value, or the mean of the two middle values of an even count;
// NaN for no values.
inline double median(std::vector<double> values)
{
    if (values.empty())
    {
        return std::numeric_limits<double>::quiet_NaN();
    }
    std::sort(values.begin(), values.end());
    const std::size_t middle = values.size() / 2;
    return values.size() % 2 == 1 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

} // namespace sph
