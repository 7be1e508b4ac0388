#include "CanonicalDictionary.hpp"

#include <cstdio>
#include <cstdlib>

namespace sph
{

namespace
{

// The shortest %g form that reads back to the same double.
std::string canonicalNumber(double value)
{
    char buffer[40];
    for (int digits = 15; digits <= 17; ++digits)
    {
        std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
        if (std::strtod(buffer, nullptr) == value)
        {
            break;
        }
    }
    return buffer;
}

std::string canonicalItem(const Item& item)
{
    switch (item.kind())
    {
    case Item::Kind::Number:
        return canonicalNumber(item.number());
    case Item::Kind::List:
    {
        std::string text = "(";
        for (std::size_t i = 0; i < item.items().size(); ++i)
        {
            text += (i ? " " : "") + canonicalItem(item.items()[i]);
        }
        return text + ")";
    }
    default:
        return item.toText();
    }
}

void collect(const Dictionary& dict, const std::string& prefix, std::vector<CanonicalEntry>& out)
{
    for (const Entry& entry : dict.entries())
    {
        const std::string path = prefix.empty() ? entry.key() : prefix + "." + entry.key();
        if (entry.isDict())
        {
            if (entry.dict().empty())
            {
                out.push_back({path, "{}", entry.keyLocation()});
            }
            collect(entry.dict(), path, out);
            continue;
        }
        std::string value;
        for (std::size_t i = 0; i < entry.items().size(); ++i)
        {
            value += (i ? " " : "") + canonicalItem(entry.items()[i]);
        }
        out.push_back({path, value, entry.keyLocation()});
    }
}

} // namespace

std::vector<CanonicalEntry> canonicalEntries(const Dictionary& dict)
{
    std::vector<CanonicalEntry> entries;
    collect(dict, "", entries);
    return entries;
}

std::vector<std::string> canonicalLines(const Dictionary& dict)
{
    std::vector<std::string> lines;
    for (const auto& entry : canonicalEntries(dict))
    {
        lines.push_back(entry.line());
    }
    return lines;
}

} // namespace sph
