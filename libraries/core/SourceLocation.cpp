#include "SourceLocation.hpp"

namespace sph
{

SourceText::SourceText(std::string displayName, const std::string& text,
                       std::vector<std::string> includedFrom)
    : displayName_(std::move(displayName)), includedFrom_(std::move(includedFrom))
{
    std::string current;
    for (char c : text)
    {
        if (c == '\n')
        {
            lines_.push_back(current);
            current.clear();
        }
        else if (c != '\r')
        {
            current += c;
        }
    }
    lines_.push_back(current);
}

const std::string& SourceText::line(int number) const
{
    static const std::string empty;
    if (number < 1 || number > lineCount())
    {
        return empty;
    }
    return lines_[static_cast<std::size_t>(number - 1)];
}

std::string SourceLocation::prefix() const
{
    if (!source)
    {
        return {};
    }
    if (line <= 0)
    {
        return source->displayName();
    }
    return source->displayName() + ":" + std::to_string(line) + ":" + std::to_string(column);
}

} // namespace sph
