#include "TextFile.hpp"

#include "InputError.hpp"

#include <fstream>
#include <sstream>

namespace sph
{

std::string readTextFile(const std::filesystem::path& path, const std::string& what,
                         std::vector<std::string> notes)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
    {
        throw InputError("cannot read " + what + " '" + path.string() + "'", std::move(notes));
    }
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace sph
