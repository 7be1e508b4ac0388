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
// start, with `hint` (e.g. where the program is looked for). The program runs in a process
// group of its own and gets SIGTERM when this process dies, however it dies (SIGKILL too):
// sphStudy's children die with it (issue 31 item 11).
int runProgram(const std::filesystem::path& program, const std::vector<std::string>& args,
               const std::filesystem::path& log, const std::filesystem::path& workingDir,
               const std::string& hint);

// From now on SIGTERM, SIGINT and SIGHUP of this process go to the program runProgram runs (a
// graceful stop for sphSolid), and this process ends with that signal once the program has
// ended, or before starting the next one (sphStudy: the variant under way is not recorded and
// runs again when the study resumes).
void forwardStopSignals();

// The executable `name` in a folder of $PATH, if any.
std::optional<std::filesystem::path> findInPath(const std::string& name);

} // namespace sph
