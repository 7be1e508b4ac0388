#include "InputError.hpp"

#include <algorithm>
#include <cstdio>

namespace sph
{

namespace
{

std::string& programNameStorage()
{
    static std::string name = "sphSolid";
    return name;
}

std::string build(const SourceLocation& where, const std::string& message,
                  const std::vector<std::string>& notes)
{
    return "--> " + InputError::programName() + " FATAL INPUT ERROR\n" +
           formatDiagnostic(where, message, notes);
}

// A binary file must not cut the message short (what() is a C string) or garble the terminal.
std::string printable(const std::string& text)
{
    std::string result;
    for (const char c : text)
    {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 && c != '\n' && c != '\t')
        {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
            result += escaped;
        }
        else
        {
            result += c;
        }
    }
    return result;
}

// A message that quotes user text (a key of megabytes, say) keeps its start and end.
std::string shortened(const std::string& text)
{
    constexpr std::size_t limit = 1000;
    if (text.size() <= limit)
    {
        return text;
    }
    return text.substr(0, limit / 2) + " [... " + std::to_string(text.size() - limit) +
           " characters ...] " + text.substr(text.size() - limit / 2);
}

} // namespace

std::string formatDiagnostic(const SourceLocation& where, const std::string& message,
                             const std::vector<std::string>& notes)
{
    std::string text;
    const std::string prefix = where.prefix();
    text += shortened(prefix.empty() ? message : prefix + ": " + message);
    text += '\n';
    if (where.known() && where.line > 0)
    {
        const std::string& line = where.source->line(where.line);
        if (!line.empty())
        {
            // A long line (generated input, a huge key) is shown as a window around the
            // error, not whole.
            constexpr std::size_t window = 120;
            const std::size_t column = static_cast<std::size_t>(std::max(1, where.column)) - 1;
            std::size_t first = 0;
            std::string shown = line;
            std::string lead;
            if (line.size() > window)
            {
                first = std::min(column > window / 2 ? column - window / 2 : 0, line.size() - window);
                shown = line.substr(first, window);
                lead = first > 0 ? "..." : "";
                if (first + window < line.size())
                {
                    shown += "...";
                }
            }
            text += "    " + lead + shown + '\n';
            // Tabs before the caret keep their width so the caret lines up under the text.
            std::string pad(lead.size(), ' ');
            for (std::size_t i = first; i < column && i < line.size(); ++i)
            {
                pad += line[i] == '\t' ? '\t' : ' ';
            }
            const auto length = static_cast<std::size_t>(std::max(1, where.length));
            const std::size_t room = first + window > column ? first + window - column : 1;
            text += "    " + pad + '^' + std::string(std::min(length, std::max<std::size_t>(room, 1)) - 1, '~') +
                    '\n';
        }
    }
    for (const std::string& note : notes)
    {
        if (!note.empty()) // e.g. a "did you mean" that found nothing
        {
            text += shortened(note) + '\n';
        }
    }
    return printable(text);
}

InputError::InputError(SourceLocation where, std::string message, std::vector<std::string> notes)
    : std::runtime_error(build(where, message, notes)), where_(std::move(where)),
      message_(std::move(message)), notes_(std::move(notes))
{
}

InputError::InputError(std::string message, std::vector<std::string> notes)
    : InputError(SourceLocation{}, std::move(message), std::move(notes))
{
}

void InputError::setProgramName(std::string name)
{
    programNameStorage() = std::move(name);
}

const std::string& InputError::programName()
{
    return programNameStorage();
}

} // namespace sph
