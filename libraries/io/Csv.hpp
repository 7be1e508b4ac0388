#pragma once
// One CSV field as RFC 4180 writes it: quoted when it holds a comma, a double quote, CR or LF,
// with each double quote doubled; as it is otherwise.

#include <string>

namespace sph
{

inline std::string csvField(const std::string& text)
{
    if (text.find_first_of(",\"\r\n") == std::string::npos)
    {
        return text;
    }
    std::string quoted = "\"";
    for (const char c : text)
    {
        quoted += c;
        if (c == '"')
        {
            quoted += '"';
        }
    }
    return quoted + "\"";
}

} // namespace sph
