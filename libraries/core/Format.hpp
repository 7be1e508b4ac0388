#pragma once
// Numbers in messages and summaries: as short as they can be (1.67e+06, 1.5, 0.001), not
// std::to_string's fixed six decimals (1670000.000000).

#include <charconv>
#include <cstdio>
#include <string>

namespace sph
{

// %g with `significant` digits: 1.5, 0.0015, 1.67e+06.
inline std::string formatNumber(double value, int significant = 6)
{
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.*g", significant, value);
    return buffer;
}

// The shortest text that reads back (strtod) as exactly `value`: 0.02, not
// 0.020000000000000000 or 0.019999999999999997 (std::to_chars' round-trip guarantee).
inline std::string formatShortest(double value)
{
    char buffer[40];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

// Fixed with `decimals` digits after the point: 0.449, 17608 (decimals 0).
inline std::string formatFixed(double value, int decimals)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
}

// Scientific with `decimals` digits after the point: 4.775e-04 (columns of figures).
inline std::string formatScientific(double value, int decimals = 3)
{
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.*e", decimals, value);
    return buffer;
}

} // namespace sph
