#include "solver/RunLog.hpp"

#include <sys/resource.h>

#include <cstdio>
#include <ostream>

namespace sph
{

RunLog::RunLog(std::ostream& out, double progressSeconds)
    : out_(out), progressSeconds_(progressSeconds), start_(Clock::now()), lastProgress_(start_)
{
}

void RunLog::line(const std::string& text)
{
    out_ << text << '\n' << std::flush;
}

void RunLog::header(const std::vector<std::string>& lines)
{
    for (const auto& text : lines)
    {
        out_ << text << '\n';
    }
    out_ << std::flush;
}

void RunLog::startTimer(double startTime, double endTime, std::size_t particles)
{
    start_ = Clock::now();
    lastProgress_ = start_;
    startTime_ = startTime;
    endTime_ = endTime;
    particles_ = particles;
}

double RunLog::elapsedSeconds() const
{
    return std::chrono::duration<double>(Clock::now() - start_).count();
}

bool RunLog::progressDue() const
{
    return std::chrono::duration<double>(Clock::now() - lastProgress_).count() >= progressSeconds_;
}

void RunLog::progress(long step, long stepsDone, double time, double deltaT, double drift,
                      bool haveDrift)
{
    lastProgress_ = Clock::now();
    const double elapsed = elapsedSeconds();
    const double rate = elapsed > 0.0 ? static_cast<double>(particles_) * stepsDone / elapsed : 0.0;
    const double fraction = (time - startTime_) / (endTime_ - startTime_);
    const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    char text[256];
    if (haveDrift)
    {
        std::snprintf(text, sizeof text,
                      "Step %-9ld t = %.6e s  dt = %.3e s  drift = %+.2e  %.3e particle-steps/s  "
                      "ETA %.0f s",
                      step, time, deltaT, drift, rate, eta);
    }
    else
    {
        std::snprintf(text, sizeof text,
                      "Step %-9ld t = %.6e s  dt = %.3e s  %.3e particle-steps/s  ETA %.0f s", step,
                      time, deltaT, rate, eta);
    }
    line(text);
}

double RunLog::peakMemoryMB()
{
    struct rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

RunSummary RunLog::finish(long steps, double time)
{
    RunSummary summary;
    summary.steps = steps;
    summary.particles = particles_;
    summary.wallSeconds = elapsedSeconds();
    summary.particleStepsPerSecond =
        summary.wallSeconds > 0.0 ? static_cast<double>(particles_) * steps / summary.wallSeconds
                                  : 0.0;
    summary.peakMemoryMB = peakMemoryMB();
    summary.finalTime = time;
    summary.outputSeconds = outputSeconds_;
    const double compute = summary.wallSeconds - outputSeconds_;
    summary.computeParticleStepsPerSecond =
        compute > 0.0 ? static_cast<double>(particles_) * steps / compute : 0.0;
    char text[320];
    std::snprintf(text, sizeof text,
                  "End: %ld steps to t = %.6e s in %.3f s wall (%.3f s of it writing VTK), "
                  "%.3e particle-steps/s (%.3f us per particle-step without output), peak memory "
                  "%.1f MB",
                  steps, time, summary.wallSeconds, outputSeconds_, summary.particleStepsPerSecond,
                  summary.computeParticleStepsPerSecond > 0
                      ? 1e6 / summary.computeParticleStepsPerSecond
                      : 0.0,
                  summary.peakMemoryMB);
    line(text);
    return summary;
}

} // namespace sph
