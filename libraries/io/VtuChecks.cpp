#include "io/VtuChecks.hpp"

#include "core/Format.hpp"
#include "core/InputError.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>

namespace sph
{

namespace
{

// A value in a message: the shortest form that reads back exactly (0.5, 7, 1e+300, nan), so
// that 7.0000001 is not shown as a whole 7.
std::string exact(double value)
{
    for (int digits = 6; digits < 17; ++digits)
    {
        const std::string text = formatNumber(value, digits);
        if (std::strtod(text.c_str(), nullptr) == value)
        {
            return text;
        }
    }
    return formatNumber(value, 17);
}

} // namespace

VtuChecks::VtuChecks(const VtuData& data, std::string subject, std::string hint)
    : data_(data), subject_(std::move(subject)), hint_(std::move(hint))
{
}

void VtuChecks::fail(const std::string& problem) const
{
    throw InputError(subject_ + ": " + problem, {hint_});
}

void VtuChecks::failAt(const std::string& name, const VtuArray& array, std::size_t index,
                       const std::string& problem) const
{
    const auto components = static_cast<std::size_t>(std::max(1, array.components));
    if (perPoint(array))
    {
        fail(particle(index / components) + ": its array '" + name + "' " + problem);
    }
    fail("its field data '" + name + "'" +
         (array.values.size() > 1 ? " (value " + std::to_string(index) + ")" : "") + " " + problem);
}

// A particle by index, with its position when the position itself is sound.
std::string VtuChecks::particle(std::size_t index) const
{
    std::string text = "particle " + std::to_string(index);
    if (3 * index + 2 < data_.points.size())
    {
        const double* x = &data_.points[3 * index];
        if (std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]))
        {
            text += " (at " + formatNumber(x[0]) + " " + formatNumber(x[1]) + " " +
                    formatNumber(x[2]) + ")";
        }
    }
    return text;
}

// Arrays taken from the point data are per point; the others are field data.
bool VtuChecks::perPoint(const VtuArray& array) const
{
    for (const auto& [name, candidate] : data_.pointData)
    {
        if (&candidate == &array)
        {
            return true;
        }
    }
    return false;
}

void VtuChecks::finitePoints() const
{
    for (std::size_t i = 0; i < data_.points.size(); ++i)
    {
        if (!std::isfinite(data_.points[i]))
        {
            const double* x = &data_.points[i - i % 3];
            fail(particle(i / 3) + " has the position (" + formatNumber(x[0]) + " " +
                 formatNumber(x[1]) + " " + formatNumber(x[2]) +
                 "); every coordinate must be finite");
        }
    }
}

const VtuArray& VtuChecks::pointArray(const std::string& name, int components,
                                      const std::string& whenMissing) const
{
    const auto found = data_.pointData.find(name);
    if (found == data_.pointData.end())
    {
        fail("it has no array '" + name + "'" + (whenMissing.empty() ? "" : " " + whenMissing));
    }
    const VtuArray& array = found->second;
    if (array.components != components)
    {
        fail("its array '" + name + "' has " + std::to_string(array.components) +
             " components, not " + std::to_string(components));
    }
    const std::size_t expected = data_.pointCount() * static_cast<std::size_t>(components);
    if (array.values.size() != expected)
    {
        fail("its array '" + name + "' holds " + std::to_string(array.values.size()) +
             " values for " + std::to_string(data_.pointCount()) + " particles (" +
             std::to_string(expected) + " expected)");
    }
    finite(name, array);
    return array;
}

const VtuArray& VtuChecks::fieldArray(const std::string& name, std::size_t size) const
{
    const auto found = data_.fieldData.find(name);
    if (found == data_.fieldData.end())
    {
        fail("it has no field data '" + name + "'");
    }
    const VtuArray& array = found->second;
    if (size > 0 && array.values.size() != size)
    {
        fail("its field data '" + name + "' holds " + std::to_string(array.values.size()) +
             " values, not " + std::to_string(size));
    }
    finite(name, array);
    return array;
}

void VtuChecks::finite(const std::string& name, const VtuArray& array) const
{
    for (std::size_t i = 0; i < array.values.size(); ++i)
    {
        if (!std::isfinite(array.values[i]))
        {
            failAt(name, array, i, "is " + exact(array.values[i]) + "; it must be finite");
        }
    }
}

void VtuChecks::positive(const std::string& name, const VtuArray& array) const
{
    for (std::size_t i = 0; i < array.values.size(); ++i)
    {
        if (!(array.values[i] > 0.0))
        {
            failAt(name, array, i, "is " + exact(array.values[i]) + "; it must be > 0");
        }
    }
}

void VtuChecks::wholeNumbers(const std::string& name, const VtuArray& array, double lowest,
                             double highest, const std::string& meaning) const
{
    for (std::size_t i = 0; i < array.values.size(); ++i)
    {
        const double value = array.values[i];
        if (!(value >= lowest && value <= highest) || value != std::floor(value))
        {
            failAt(name, array, i,
                   "is " + exact(value) + "; it must be a whole number from " + exact(lowest) +
                       " to " + exact(highest) + " (" + meaning + ")");
        }
    }
}

// VTK's XML reader takes a piece's NumberOfPoints and NumberOfCells unchecked (a negative one
// crashed it, issue 31): they must be whole numbers >= 0, checked in the XML header (the text
// before any appended binary data) before VTK sees the file.
void checkVtuPieceSizes(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    std::string header;
    std::string chunk(1 << 16, '\0');
    while (in && header.find("<AppendedData") == std::string::npos && header.size() < (64u << 20))
    {
        in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        header.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    }
    header = header.substr(0, header.find("<AppendedData"));
    static const std::regex size(R"re((NumberOf(?:Points|Cells))\s*=\s*"([^"]*)")re");
    for (auto it = std::sregex_iterator(header.begin(), header.end(), size);
         it != std::sregex_iterator(); ++it)
    {
        const std::string value = (*it)[2];
        const bool whole = !value.empty() && value.size() <= 18 &&
                           std::all_of(value.begin(), value.end(),
                                       [](char c) { return c >= '0' && c <= '9'; });
        if (!whole)
        {
            throw InputError("cannot read '" + file.string() + "': its " + std::string((*it)[1]) +
                                 " is \"" + value + "\", not a whole number >= 0",
                             {"The file is damaged; write it again (sphParticles, or the run "
                              "that wrote it)."});
        }
    }
}


} // namespace sph
