#pragma once
// Starting another program without a shell (sphStudy runs sphParticles, sphSolid and gnuplot;
// the tests run the applications): an argument vector, a working folder and a log file, so
// that no name or path from a case is ever interpreted as shell text (a level name or a case
// path with a quote in it must not run a command).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sph
{

// Runs `program args...` in `workingDir` (the current folder if empty) with stdout and stderr
// to `log`; returns the exit code (128 + signal if killed). Throws InputError if it cannot
// start, with `hint` (e.g. where the program is looked for).
int runProgram(const std::filesystem::path& program, const std::vector<std::string>& args,
               const std::filesystem::path& log, const std::filesystem::path& workingDir,
               const std::string& hint);

// The executable `name` in a folder of $PATH, if any.
std::optional<std::filesystem::path> findInPath(const std::string& name);

} // namespace sph
