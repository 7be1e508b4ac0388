#pragma once
// A file a case names by a key (a study's reference table, a measured surface profile): named
// relative to the case folder, inside it (no absolute name, no '..' out of it: a case holds
// what it compares with), and a regular file that can be read. One check for every such file,
// so each refuses the same things at the key's place, with the files that are there.

#include "core/Schema.hpp"

#include <filesystem>
#include <string>
#include <string_view>

namespace sph
{

// The file named by the string key `key`, relative to `caseDir`. An InputError at the key's
// value, naming `what` ("the reference table"), when it is outside the case folder or cannot
// be read; `hint` is the last note.
std::filesystem::path caseFile(const Params& p, std::string_view key,
                               const std::filesystem::path& caseDir, const std::string& what,
                               const std::string& hint);

} // namespace sph
