#pragma once
// The run log on standard output: a header, a progress line at most once a second (step,
// time, Δt, energy drift, particle-steps/s, ETA) and a summary (wall time, particle-steps/s,
// peak memory).

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

class RunLog
{
public:
    explicit RunLog(std::ostream& out, double progressSeconds = 1.0);

    void line(const std::string& text);
    void header(const std::vector<std::string>& lines);
    void startTimer(double startTime, double endTime, std::size_t particles);
    // Whether a progress line is due (checked before the step's force evaluation).
    bool progressDue() const;
    void progress(long step, long stepsDone, double time, double deltaT, double drift,
                  bool haveDrift);
    RunSummary finish(long steps, double time);
    // Time spent writing output, excluded from the compute rate.
    void addOutputSeconds(double seconds) { outputSeconds_ += seconds; }
    double elapsedSeconds() const;

    // Resident-set peak of this process [MB].
    static double peakMemoryMB();

private:
    using Clock = std::chrono::steady_clock;
    std::ostream& out_;
    double progressSeconds_;
    Clock::time_point start_;
    mutable Clock::time_point lastProgress_;
    double startTime_ = 0.0;
    double endTime_ = 0.0;
    std::size_t particles_ = 0;
    double outputSeconds_ = 0.0;
};

} // namespace sph
