#pragma once
// The run log on standard output: a header, a progress line at most once a second (step,
// time and % of endTime, elapsed wall time, ETA, Δt, energy drift, particle-steps/s) and a
// summary (wall time, particle-steps/s, peak memory). On a terminal the progress line is
// rewritten in place (carriage return); in a file (or pipe) each report is a line of its own.

#include <chrono>
#include <iosfwd>
#include <string>
#include <vector>

namespace sph
{

struct RunSummary
{
    long steps = 0;
    std::size_t particles = 0;
    double wallSeconds = 0.0;
    double particleStepsPerSecond = 0.0;
    double peakMemoryMB = 0.0;
    double finalTime = 0.0;
    double outputSeconds = 0.0;               // writing VTK files
    double computeParticleStepsPerSecond = 0.0; // excluding the output
};

// The wall time left to endTime from the recent rate of simulated time per wall second, not
// from the steps: Δt is not constant (it shrinks 5.6× as the Taylor bar flattens, while the
// cost of a step stays), so "elapsed × (1 − f)/f" is wrong by the factor the step shrank.
// The rate is that of an exponentially weighted window of the past wall time (time constant
// τ = `windowSeconds`, two progress intervals in the log): the mean of ds/dw weighted by
// exp(−age/τ), each interval between two samples at its own mean rate, so uneven intervals
// (one holding a slow VTK write) count by their length. Short, as the rate after Δt has
// shrunk is the one that holds for the rest of the run (in RunLogTest's Taylor-bar-like run
// the estimate is within 2 % of the truth 8 s after Δt stopped shrinking, with τ = 5 s only
// after 24 s; the constant-step estimate is then 3.6× short); a window rather
// than the last interval alone, so that an interval holding an output write (slower than one
// without) does not make the ETA jump at every write.
class EtaEstimator
{
public:
    explicit EtaEstimator(double windowSeconds = 2.0) : window_(windowSeconds) {}

    // The first sample: wall seconds, simulated time.
    void start(double wall, double time);
    // A later sample (wall time not before the previous one's).
    void add(double wall, double time);
    // Simulated seconds per wall second (0 before any interval of wall time).
    double rate() const;
    // Wall seconds until `endTime` is reached at the recent rate; negative when unknown (no
    // interval yet, or time does not advance).
    double remaining(double endTime) const;

private:
    double window_;
    double lastWall_ = 0.0;
    double lastTime_ = 0.0;
    double weightedWall_ = 0.0; // ∫ exp(−age/τ) dw
    double weightedTime_ = 0.0; // ∫ exp(−age/τ) (ds/dw) dw
};

// A duration for the log: "42s", "3m07s", "2h05m" (negative: "?").
std::string formatDuration(double seconds);

class RunLog
{
public:
    // inPlace: rewrite the progress line in place (for a terminal: stdoutIsTerminal()).
    explicit RunLog(std::ostream& out, double progressSeconds = 1.0, bool inPlace = false);
    ~RunLog();
    RunLog(const RunLog&) = delete;
    RunLog& operator=(const RunLog&) = delete;

    void line(const std::string& text);
    void header(const std::vector<std::string>& lines);
    void startTimer(double startTime, double endTime, std::size_t particles);
    // Whether a progress line is due (checked before the step's force evaluation).
    bool progressDue() const;
    // `note`: the time integrator's word on its step (e.g. the measured omega dt), appended.
    void progress(long step, long stepsDone, double time, double deltaT, double drift,
                  bool haveDrift, const std::string& note = "");
    RunSummary finish(long steps, double time);
    // Time spent writing output, excluded from the compute rate.
    void addOutputSeconds(double seconds) { outputSeconds_ += seconds; }
    double elapsedSeconds() const;

    // Resident-set peak of this process [MB].
    static double peakMemoryMB();
    // Whether standard output is a terminal (isatty): then the progress line updates in place.
    static bool stdoutIsTerminal();

private:
    using Clock = std::chrono::steady_clock;
    // Ends a progress line left open on the terminal, so the next text starts on a new line.
    void closeProgressLine();

    std::ostream& out_;
    double progressSeconds_;
    bool inPlace_;
    bool progressOpen_ = false; // a progress line without its newline is on the terminal
    Clock::time_point start_;
    mutable Clock::time_point lastProgress_;
    double endTime_ = 0.0;
    std::size_t particles_ = 0;
    double outputSeconds_ = 0.0;
    EtaEstimator eta_;
};

} // namespace sph
