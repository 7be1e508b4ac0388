#include "InputError.hpp"

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

} // namespace

std::string formatDiagnostic(const SourceLocation& where, const std::string& message,
                             const std::vector<std::string>& notes)
{
    std::string text;
    const std::string prefix = where.prefix();
    text += prefix.empty() ? message : prefix + ": " + message;
    text += '\n';
    if (where.known() && where.line > 0)
    {
        const std::string& line = where.source->line(where.line);
        if (!line.empty())
        {
            text += "    " + line + '\n';
            // Tabs before the caret keep their width so the caret lines up under the text.
            std::string pad;
            for (int i = 0; i + 1 < where.column && i < static_cast<int>(line.size()); ++i)
            {
                pad += line[static_cast<std::size_t>(i)] == '\t' ? '\t' : ' ';
            }
            const int length = std::max(1, where.length);
            text += "    " + pad + '^' + std::string(static_cast<std::size_t>(length - 1), '~') +
                    '\n';
        }
    }
    for (const std::string& note : notes)
    {
        if (!note.empty()) // e.g. a "did you mean" that found nothing
        {
            text += note + '\n';
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
