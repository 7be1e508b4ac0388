#include "core/PlainName.hpp"

#include "core/InputError.hpp"

#include <algorithm>
#include <cctype>

namespace sph
{

bool isPlainName(const std::string& name)
{
    const auto plain = [](char c)
    {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '+' ||
               c == '-';
    };
    return !name.empty() && name.size() <= 64 &&
           (std::isalnum(static_cast<unsigned char>(name[0])) || name[0] == '_') &&
           std::all_of(name.begin(), name.end(), plain);
}

void requirePlainName(const Entry& entry, const std::string& what, const std::string& usedAs)
{
    if (!isPlainName(entry.key()))
    {
        throw InputError(entry.keyLocation(),
                         what + " '" + entry.key() + "' is not a plain name: it is used in " +
                             usedAs,
                         {"Use letters, digits and _ . + - (at most 64, starting with a letter, "
                          "a digit or _), e.g. dx0.5mm or ULgradF."});
    }
}

} // namespace sph
