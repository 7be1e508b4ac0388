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

// Length of the valid UTF-8 sequence starting at text[i] (1 to 4), or 0 when the bytes there
// are not one (a stray continuation byte, an overlong form, a surrogate, a cut sequence).
std::size_t utf8Length(const std::string& text, std::size_t i)
{
    const auto byte = [&](std::size_t k)
    { return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u; };
    const unsigned lead = byte(i);
    std::size_t length = 0;
    unsigned low = 0x80;
    unsigned high = 0xbf; // the allowed range of the second byte
    if (lead < 0x80)
    {
        return 1;
    }
    if (lead >= 0xc2 && lead <= 0xdf)
    {
        length = 2;
    }
    else if (lead >= 0xe0 && lead <= 0xef)
    {
        length = 3;
        low = lead == 0xe0 ? 0xa0 : 0x80;
        high = lead == 0xed ? 0x9f : 0xbf;
    }
    else if (lead >= 0xf0 && lead <= 0xf4)
    {
        length = 4;
        low = lead == 0xf0 ? 0x90 : 0x80;
        high = lead == 0xf4 ? 0x8f : 0xbf;
    }
    else
    {
        return 0;
    }
    for (std::size_t k = 1; k < length; ++k)
    {
        const unsigned next = byte(i + k);
        if (next < (k == 1 ? low : 0x80) || next > (k == 1 ? high : 0xbf))
        {
            return 0;
        }
    }
    return length;
}

// How the text at byte i is shown: one character of `length` bytes, or one byte escaped
// (control bytes, C1 controls, bytes that are not UTF-8 text).
struct Shown
{
    std::size_t length;
    bool escaped;
};

Shown shownAt(const std::string& text, std::size_t i)
{
    const auto byte = static_cast<unsigned char>(text[i]);
    const std::size_t length = utf8Length(text, i);
    const bool control =
        (byte < 0x20 && byte != '\n' && byte != '\t') || byte == 0x7f ||
        (length == 2 && byte == 0xc2 && static_cast<unsigned char>(text[i + 1]) < 0xa0);
    return length == 0 || control ? Shown{1, true} : Shown{length, false};
}

// A binary file must not cut the message short (what() is a C string) or garble the terminal:
// control bytes and bytes that are not UTF-8 text are shown escaped, \x00 or \xff.
std::string printable(const std::string& text)
{
    std::string result;
    for (std::size_t i = 0; i < text.size();)
    {
        const Shown shown = shownAt(text, i);
        if (shown.escaped)
        {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", static_cast<unsigned char>(text[i]));
            result += escaped;
        }
        else
        {
            result.append(text, i, shown.length);
        }
        i += shown.length;
    }
    return result;
}

// The blanks that bring the caret under byte `end` of `line` shown from byte `first`: tabs
// keep their width, an escaped byte takes four columns, a UTF-8 character one.
std::string caretPadding(const std::string& line, std::size_t first, std::size_t end)
{
    std::string pad;
    for (std::size_t i = first; i < end && i < line.size();)
    {
        const Shown shown = shownAt(line, i);
        pad += shown.escaped ? std::string(4, ' ') : line[i] == '\t' ? "\t" : " ";
        i += shown.length;
    }
    return pad;
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
            const std::string pad =
                std::string(lead.size(), ' ') + caretPadding(line, first, column);
            const auto length = static_cast<std::size_t>(std::max(1, where.length));
            const std::size_t room = first + window > column ? first + window - column : 1;
            text += "    " + pad + '^' + std::string(std::min(length, std::max<std::size_t>(room, 1)) - 1, '~') +
                    '\n';
        }
    }
    if (where.known())
    {
        for (const std::string& includer : where.source->includedFrom())
        {
            text += "    included from " + includer + '\n';
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
