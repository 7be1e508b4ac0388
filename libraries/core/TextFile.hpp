#pragma once
// Reading a whole text file, with the one error message every reader gives when it cannot.

#include <filesystem>
#include <string>
#include <vector>

namespace sph
{

// The content of `path`; an InputError "cannot read <what> '<path>'" with `notes` otherwise.
std::string readTextFile(const std::filesystem::path& path, const std::string& what,
                         std::vector<std::string> notes);

} // namespace sph
