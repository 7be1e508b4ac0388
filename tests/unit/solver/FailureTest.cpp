// Numerical failure stops the run cleanly: the message names step, time, particle and
// quantity; the last good state is written (marked not restartable); exit code 2.
#include "core/Application.hpp"
#include "io/PvdSeries.hpp"
#include "io/VtuFile.hpp"
#include "support/CaseRunner.hpp"

using namespace sph;

TEST_CASE("an unstable time step stops with a diagnosis and the last good state", "[failure]")
{
    test::TempDir dir;
    const auto caseDir = test::copyTutorial("bar1D/dykaBar", dir.path());
    REQUIRE(test::runParticles(caseDir) == 0);
    // courant 1.9 with h = 1.5 dx: the leapfrog is unstable for the highest modes.
    try
    {
        test::runSolver(caseDir, {"-set", "courant=1.9", "-set", "writeInterval=1"});
        FAIL("the run did not fail");
    }
    catch (const NumericalFailure& failure)
    {
        const std::string message = failure.what();
        CHECK_THAT(message, Catch::Contains("step "));
        CHECK_THAT(message, Catch::Contains("t = "));
        CHECK_THAT(message, Catch::Contains("particle "));
        CHECK_THAT(message, Catch::Contains("body 'bar'"));
        CHECK((message.find("det F") != std::string::npos ||
               message.find("particle order") != std::string::npos ||
               message.find("internal force") != std::string::npos));
        CHECK_THAT(message, Catch::Contains("The last good state"));
    }
    PvdSeries series(caseDir / "VTK" / "dykaBar.pvd");
    series.load();
    REQUIRE(series.entries().size() >= 2);
    const VtuData last = readVtu(caseDir / "VTK" / series.entries().back().file);
    CHECK(last.fieldData.at("restart:restartable").values.at(0) == 0.0);
    for (double J : last.pointData.at("volumeRatio").values)
    {
        CHECK(J > 0.0); // the written state is the good one
    }

    std::string output;
    CHECK(test::runProcess("sphSolid", {"-case", caseDir.string(), "-set", "courant=1.9", "-set",
                                        "writeInterval=1"},
                           &output) == 2);
    CHECK_THAT(output, Catch::Contains("NUMERICAL FAILURE"));
}
