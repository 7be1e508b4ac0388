// The progress line (issue 32 item 4): an ETA from the recent rate of simulated time per wall
// second, not from the step count (Δt shrinks 5.6× on the Taylor bar and the constant-step
// ETA was 4× short); elapsed time and % of endTime; one line rewritten in place on a terminal.
#include "solver/RunLog.hpp"
#include "support/TestSupport.hpp"

#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

using namespace sph;

namespace
{

// A run whose steps all cost 1 ms of wall time while Δt shrinks 5.6× between 40 % and 45 % of
// endTime (geometrically), then stays: the Taylor bar's shape. Reports once a wall second:
// (wall seconds, simulated time); the last pair is the end of the run.
std::vector<std::pair<double, double>> shrinkingStepRun(double endTime)
{
    const double finalStep = endTime / 200000.0;
    const auto step = [&](double t) {
        const double a = 0.40 * endTime;
        const double b = 0.45 * endTime;
        if (t < a)
        {
            return 5.6 * finalStep;
        }
        if (t > b)
        {
            return finalStep;
        }
        return 5.6 * finalStep * std::pow(1.0 / 5.6, (t - a) / (b - a));
    };
    std::vector<std::pair<double, double>> reports{{0.0, 0.0}};
    double t = 0.0;
    long steps = 0;
    while (t < endTime)
    {
        t += step(t);
        ++steps;
        if (steps % 1000 == 0 || t >= endTime)
        {
            reports.emplace_back(static_cast<double>(steps) / 1000.0, t);
        }
    }
    return reports;
}

} // namespace

TEST_CASE("ETA: from the recent rate of simulated time, right where constant steps are 4x off",
          "[runLog]")
{
    const double endTime = 80e-6;
    const auto reports = shrinkingStepRun(endTime);
    const double total = reports.back().first; // wall seconds of the whole run
    REQUIRE(total == Approx(129.05).margin(0.1));
    EtaEstimator eta;
    eta.start(reports.front().first, reports.front().second);
    bool checked = false;
    for (std::size_t k = 1; k + 1 < reports.size(); ++k)
    {
        const auto [wall, time] = reports[k];
        eta.add(wall, time);
        const double truth = total - wall;
        // The old estimate: elapsed × (1 − f)/f, as if every step were as long as the mean.
        const double fraction = time / endTime;
        const double constantSteps = wall * (1.0 - fraction) / fraction;
        if (wall == 27.0) // 8 s after Δt stopped shrinking (at 19 s, 45 % of endTime)
        {
            INFO("remaining " << truth << " s, estimate " << eta.remaining(endTime)
                              << " s, constant-step estimate " << constantSteps << " s");
            CHECK(truth > 3.5 * constantSteps); // the old ETA: 28 s for 102 s
            CHECK(eta.remaining(endTime) == Approx(truth).epsilon(0.02));
            checked = true;
        }
        if (wall >= 40.0)
        {
            CHECK(eta.remaining(endTime) == Approx(truth).epsilon(1e-3).margin(2e-3)); // a step: 1 ms
        }
    }
    CHECK(checked);
}

TEST_CASE("ETA: constant steps give the elapsed-time estimate, none before a rate", "[runLog]")
{
    EtaEstimator eta(2.0);
    eta.start(0.0, 1.0); // a restart: the run starts at t = 1
    CHECK(eta.remaining(3.0) < 0.0);
    eta.add(0.0, 1.0); // no wall time yet
    CHECK(eta.remaining(3.0) < 0.0);
    // 0.1 s of simulated time per wall second, reports at uneven intervals.
    for (const double wall : {0.7, 1.9, 2.0, 4.5})
    {
        eta.add(wall, 1.0 + 0.1 * wall);
        CHECK(eta.rate() == Approx(0.1));
        CHECK(eta.remaining(3.0) == Approx((2.0 - 0.1 * wall) / 0.1));
    }
    // A stalled run (time does not advance) has no ETA.
    EtaEstimator stalled;
    stalled.start(0.0, 0.0);
    stalled.add(1.0, 0.0);
    CHECK(stalled.remaining(1.0) < 0.0);
}

TEST_CASE("durations in the log read as seconds, minutes, hours", "[runLog]")
{
    CHECK(formatDuration(0.2) == "0s");
    CHECK(formatDuration(42.4) == "42s");
    CHECK(formatDuration(187.0) == "3m07s");
    CHECK(formatDuration(7500.0) == "2h05m");
    CHECK(formatDuration(-1.0) == "?");
}

TEST_CASE("progress line: elapsed time, % of endTime and ETA, one line per report in a file",
          "[runLog]")
{
    std::ostringstream out;
    {
        RunLog log(out, 1.0, false);
        log.startTimer(0.0, 1e-3, 100);
        log.progress(50, 50, 2.5e-4, 5e-6, 1e-4, true);
        log.progress(100, 100, 5e-4, 5e-6, 1e-4, true);
        log.line("End");
    }
    const std::string text = out.str();
    INFO(text);
    CHECK(text.find('\r') == std::string::npos);
    std::istringstream lines(text);
    std::string first, second, last;
    std::getline(lines, first);
    std::getline(lines, second);
    std::getline(lines, last);
    CHECK_THAT(first, Catch::Matches(
                          R"(Step 50 +t = 2\.500000e-04 s   25\.0 %  elapsed [0-9]+s  ETA [0-9?][0-9hms]*  dt = 5\.000e-06 s  drift = \+1\.00e-04  .* particle-steps/s)"));
    CHECK_THAT(second, Catch::Contains("50.0 %") && Catch::Contains("elapsed "));
    CHECK(last == "End");
}

TEST_CASE("progress line on a terminal: rewritten in place, closed before the next line",
          "[runLog]")
{
    std::ostringstream out;
    {
        RunLog log(out, 1.0, true);
        log.header({"header"});
        log.startTimer(0.0, 2.0, 10);
        log.progress(1, 1, 0.5, 0.5, 0.0, false);
        log.progress(2, 2, 1.0, 0.5, 0.0, false);
        log.line("End");
        log.progress(3, 3, 1.5, 0.5, 0.0, false); // left open: the log closes it
    }
    const std::string text = out.str();
    INFO(text);
    const auto first = text.find("\rStep 1 ");
    const auto second = text.find("\rStep 2 ");
    const auto end = text.find("\nEnd\n");
    REQUIRE(text.rfind("header\n", 0) == 0);
    REQUIRE(first != std::string::npos);
    REQUIRE(second != std::string::npos);
    REQUIRE(end != std::string::npos);
    // No newline between the reports: the second overwrites the first.
    CHECK(text.find('\n', first) == end);
    CHECK(first < second);
    CHECK_THAT(text.substr(second, end - second),
               Catch::Contains(" 50.0 %") && Catch::Contains("elapsed ") && Catch::Contains("ETA "));
    CHECK(text.size() >= 1);
    CHECK(text.back() == '\n');
    CHECK_THAT(text.substr(end), Catch::Contains("\rStep 3 ") && Catch::Contains(" 75.0 %"));
}
