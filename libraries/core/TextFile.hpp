#pragma once
// Reading a whole text file, with the one error message every reader gives when it cannot.

#include <filesystem>
#include <string>
#include <vector>

namespace sph
{

// Why `path` cannot be read as a text file, "" when it can: "no such file", "it is a folder,
// not a file", "too many levels of symbolic links" (a link loop), "permission denied", ...
// Never throws (std::filesystem's own checks throw on a link loop).
std::string unreadableReason(const std::filesystem::path& path);

// The content of `path`; an InputError "cannot read <what> '<path>'" with `notes` otherwise.
std::string readTextFile(const std::filesystem::path& path, const std::string& what,
                         std::vector<std::string> notes);

} // namespace sph
