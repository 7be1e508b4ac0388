#include "solver/RunLog.hpp"

#include <sys/ioctl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace sph
{

void EtaEstimator::start(double wall, double time)
{
    lastWall_ = wall;
    lastTime_ = time;
    weightedWall_ = 0.0;
    weightedTime_ = 0.0;
}

void EtaEstimator::add(double wall, double time)
{
    const double interval = wall - lastWall_;
    if (!(interval > 0.0))
    {
        lastTime_ = time; // no wall time passed: nothing to learn a rate from
        return;
    }
    // The older intervals fade by exp(−interval/τ); this one, at its mean rate, enters with
    // the weight ∫ exp(−age/τ) over its own length.
    const double fade = std::exp(-interval / window_);
    const double weight = window_ * (1.0 - fade);
    weightedWall_ = weightedWall_ * fade + weight;
    weightedTime_ = weightedTime_ * fade + weight * (time - lastTime_) / interval;
    lastWall_ = wall;
    lastTime_ = time;
}

double EtaEstimator::rate() const
{
    return weightedWall_ > 0.0 ? weightedTime_ / weightedWall_ : 0.0;
}

double EtaEstimator::remaining(double endTime) const
{
    const double r = rate();
    if (!(r > 0.0))
    {
        return -1.0;
    }
    return std::max(endTime - lastTime_, 0.0) / r;
}

std::string formatDuration(double seconds)
{
    if (!(seconds >= 0.0) || !std::isfinite(seconds))
    {
        return "?";
    }
    const long whole = std::lround(seconds);
    char text[64];
    if (whole < 60)
    {
        std::snprintf(text, sizeof text, "%lds", whole);
    }
    else if (whole < 3600)
    {
        std::snprintf(text, sizeof text, "%ldm%02lds", whole / 60, whole % 60);
    }
    else
    {
        const long minutes = std::lround(seconds / 60.0);
        std::snprintf(text, sizeof text, "%ldh%02ldm", minutes / 60, minutes % 60);
    }
    return text;
}

RunLog::RunLog(std::ostream& out, double progressSeconds, bool inPlace)
    : out_(out), progressSeconds_(progressSeconds), inPlace_(inPlace), start_(Clock::now()),
      lastProgress_(start_), eta_(2.0 * progressSeconds)
{
}

RunLog::~RunLog()
{
    // An error leaves the run with the progress line open: its message starts on a new line.
    closeProgressLine();
}

void RunLog::closeProgressLine()
{
    if (progressOpen_)
    {
        out_ << '\n' << std::flush;
        progressOpen_ = false;
    }
}

bool RunLog::stdoutIsTerminal()
{
    return isatty(STDOUT_FILENO) == 1;
}

void RunLog::line(const std::string& text)
{
    closeProgressLine();
    out_ << text << '\n' << std::flush;
}

void RunLog::header(const std::vector<std::string>& lines)
{
    closeProgressLine();
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
    endTime_ = endTime;
    particles_ = particles;
    eta_.start(0.0, startTime);
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
                      bool haveDrift, const std::string& note)
{
    lastProgress_ = Clock::now();
    const double elapsed = elapsedSeconds();
    eta_.add(elapsed, time);
    const double rate = elapsed > 0.0 ? static_cast<double>(particles_) * stepsDone / elapsed : 0.0;
    const double percent =
        endTime_ > 0.0 ? std::clamp(100.0 * time / endTime_, 0.0, 100.0) : 100.0;
    char head[160];
    std::snprintf(head, sizeof head, "Step %-9ld t = %.6e s  %5.1f %%  elapsed %s  ETA %s  ", step,
                  time, percent, formatDuration(elapsed).c_str(),
                  formatDuration(eta_.remaining(endTime_)).c_str());
    char tail[160];
    if (haveDrift)
    {
        std::snprintf(tail, sizeof tail, "dt = %.3e s  drift = %+.2e  %.3e particle-steps/s",
                      deltaT, drift, rate);
    }
    else
    {
        std::snprintf(tail, sizeof tail, "dt = %.3e s  %.3e particle-steps/s", deltaT, rate);
    }
    std::string text = std::string(head) + tail + (note.empty() ? "" : "  " + note);
    if (!inPlace_)
    {
        line(text);
        return;
    }
    // One line rewritten in place; cut to the terminal's width, as a line that wraps would
    // leave its first rows behind at every report.
    struct winsize size{};
    if (ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 1 &&
        text.size() >= size.ws_col)
    {
        text.resize(size.ws_col - 1u);
    }
    out_ << '\r' << text << "\033[K" << std::flush; // "\033[K": clear the rest of the line
    progressOpen_ = true;
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
