// The times of the .pvd series (issue 32 item 8): ParaView shows 0.02, not
// 0.019999999999999997, while the exact time of each output stays its TimeValue.
#include "io/PvdSeries.hpp"
#include "support/TestSupport.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

using namespace sph;

TEST_CASE("series times: the fewest digits within round-off of the time", "[pvd]")
{
    CHECK(formatSeriesTime(0.0) == "0");
    CHECK(formatSeriesTime(0.02) == "0.02");
    CHECK(formatSeriesTime(std::nextafter(0.02, 0.0)) == "0.02"); // 0.019999999999999997
    CHECK(formatSeriesTime(0.49999999999999994) == "0.5");
    CHECK(formatSeriesTime(7.9999999999999871e-05) == "8e-05"); // the Taylor bar's last output
    CHECK(formatSeriesTime(0.1 + 0.2) == "0.3");
    CHECK(formatSeriesTime(2.5e-4) == "0.00025");
    CHECK(formatSeriesTime(1.234567e-5) == "1.234567e-05");
    CHECK(formatSeriesTime(3.141592653589793) == "3.14159265359"); // 12 digits: within 1e-12
    // Never further from the time than the tolerance.
    for (const double time : {1e-9 / 3.0, 2.0 / 3.0, 1234.5678901234567, 7.0 / 11.0 * 1e-5})
    {
        const double read = std::stod(formatSeriesTime(time));
        CHECK(std::abs(read - time) <= seriesTimeTolerance * time);
    }
}

TEST_CASE("series times are written short and a restart's level is kept though rounded",
          "[pvd]")
{
    test::TempDir dir;
    const auto file = dir.path() / "case.pvd";
    const double last = std::nextafter(0.5, 0.0); // an output time a little below 0.5
    {
        PvdSeries series(file);
        series.add(0.0, "case_0.vtu");
        series.add(0.1 + 0.15, "case_1.vtu");
        series.add(last, "case_2.vtu");
        series.add(0.75, "case_3.vtu");
    }
    std::ifstream in(file);
    std::ostringstream text;
    text << in.rdbuf();
    CHECK_THAT(text.str(), Catch::Contains("timestep=\"0\"") &&
                               Catch::Contains("timestep=\"0.25\"") &&
                               Catch::Contains("timestep=\"0.5\""));
    PvdSeries series(file);
    series.load();
    REQUIRE(series.entries().size() == 4);
    CHECK(series.entries()[2].time == 0.5); // as written, within the tolerance of `last`
    // A restart from the level at `last` (its exact time from the output's TimeValue) keeps
    // that level although it reads back as a little more, and drops the later ones; until the
    // level is written again its file is the good one (issue 31 item 6: a restart on a full
    // disk dropped it from the series).
    series.keepThrough(last);
    REQUIRE(series.entries().size() == 3);
    CHECK(series.entries().back().file == "case_2.vtu");
    // Written again, the level replaces its entry: the series names each file once.
    series.add(last, "case_2.vtu");
    REQUIRE(series.entries().size() == 3);
    CHECK(series.entries().back().time == last);
    series.add(0.75, "case_3.vtu");
    CHECK(series.entries().size() == 4);
}
