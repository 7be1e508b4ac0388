#pragma once
// The top-level guard every application's main() runs in: whatever escapes becomes a clean
// message and an exit code, never an uncaught exception, abort or core dump.
//   InputError        -> the formatted message, exit 1
//   NumericalFailure  -> the diagnosis, exit 2 (the last good state was written before throwing)
//   IoError           -> the file and the system's reason, exit 4 (every output already in
//                        place is intact: io/AtomicFile)
//   anything else     -> "internal error" with what() and a request to report it, exit 3
// and sphSolid returns stoppedExitCode (5) itself for a run stopped before endTime.
// A distributed run (sphSolid -parallel) says through ErrorReporting which of its processes
// prints what; this file stays free of MPI (core does not link the parallel library).

#include <functional>
#include <stdexcept>
#include <string>

namespace sph
{

// A numerical blow-up (NaN, det F <= 0, crossing particles, time step collapse). The message
// names the step, time, particle and quantity.
class NumericalFailure : public std::runtime_error
{
public:
    explicit NumericalFailure(const std::string& message) : std::runtime_error(message) {}
};

// Who prints which error when several processes run the same case. The default is a serial
// process: it prints every error and returns its exit code.
struct ErrorReporting
{
    // InputError, NumericalFailure and IoError are collective: every rank reads the same case and
    // meets them alike, so one process prints them and every process returns the exit code.
    bool printsCollective = true;
    // Put before the message of an error this process met alone (internal, out of memory), to
    // say where it happened, e.g. "[rank 1] ".
    std::string alonePrefix;
    // Called with the exit code once such an error is printed: a distributed run stops every
    // rank there (MPI_Abort), since the others would wait for this one forever. Empty: return
    // the exit code.
    std::function<void(int)> stopAll;
};

// The exit code of a sphSolid run stopped before endTime on request (SIGTERM, SIGINT, `stopAt
// writeNow`: solver/StopRequest.hpp): its last level is written and restartable, and
// postProcessing/summary.json says "stopped" and by what. Not an error: distinct from 0 so that a
// job script knows the run is not complete.
constexpr int stoppedExitCode = 5;

int guardedMain(const std::function<int()>& body, const ErrorReporting& reporting = {});

} // namespace sph
