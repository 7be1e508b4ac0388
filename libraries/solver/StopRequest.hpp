#pragma once
// A graceful stop of a running sphSolid (README "Stopping a run, restarting"):
//
//   SIGTERM, SIGINT  (a batch scheduler before its time limit, Ctrl-C) the first one asks the
//                    run to stop: the step under way is finished, its level is written
//                    (restartable: `startFrom latestTime;` continues bit-identically), the run
//                    summary says "stopped" and by which signal, and sphSolid exits with
//                    stoppedExitCode (core/Application.hpp). A second signal while it stops ends
//                    the process at once, as if the signal were not caught (exit 128 + signal in
//                    a shell; every output written before is intact: io/AtomicFile).
//   stopAt writeNow  system/controlDict is read again when its modification time changes
//                    (looked at every second, as OpenFOAM's runTimeModifiable); `stopAt
//                    writeNow;` stops the run the same way. An invalid edit is reported and the
//                    run goes on; only stopAt is taken from the file while running.
//
// A distributed run agrees on the step to stop at: every rank's request is reduced once per
// step together with the progress line's (Simulation::advance), rank 0 alone reads controlDict.

#include <signal.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace sph
{

// While it lives, SIGTERM and SIGINT are caught; the previous handlers are restored after.
class StopSignals
{
public:
    StopSignals();
    ~StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

    // The first signal caught since construction (SIGTERM, SIGINT), 0 if none.
    static int caught();
    // "SIGTERM", "SIGINT", else "signal N".
    static std::string name(int signal);

private:
    struct sigaction previousTerm_ {};
    struct sigaction previousInt_ {};
};

// What asks a run to stop, as one number the ranks reduce with their maximum: a signal wins
// over stopAt writeNow (its number is larger).
struct StopCode
{
    static constexpr int none = 0;
    static constexpr int writeNow = 1; // below every signal number that is caught
    // "SIGTERM", "stopAt writeNow" (summary.json's stoppedBy).
    static std::string describe(int code);
};

// system/controlDict's `stopAt`, read again while the run goes on.
class ControlDictWatch
{
public:
    // writeNow: the value read at the start. checkSeconds: how often the modification time is
    // looked at (wall clock).
    ControlDictWatch(std::filesystem::path caseDir, bool writeNow, double checkSeconds = 1.0);

    // Whether controlDict says `stopAt writeNow;`. When the file changed it is read and
    // validated again; an invalid file is reported through `report` (once per change) and the
    // last valid value is kept.
    bool writeNow(const std::function<void(const std::string&)>& report);

private:
    using Clock = std::chrono::steady_clock;
    std::optional<std::filesystem::file_time_type> stamp() const;

    std::filesystem::path caseDir_;
    bool writeNow_;
    std::chrono::duration<double> interval_;
    Clock::time_point lastCheck_;
    std::optional<std::filesystem::file_time_type> stamp_;
};

} // namespace sph
