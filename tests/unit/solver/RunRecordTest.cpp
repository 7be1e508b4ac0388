// What a run records and how the applications answer (issue 32 item 8), through the real
// applications: -h as -help; summary.json with the version, the git revision of the build and
// the command line; the .pvd's times as 0.0003, not 0.00030000000000000003.
#include "core/CommandLine.hpp"
#include "io/PvdSeries.hpp"
#include "io/VtuFile.hpp"
#include "solver/SolverCases.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

using namespace sph;

TEST_CASE("every application takes -h as -help", "[runRecord]")
{
    for (const std::string app : {"sphSolid", "sphParticles", "sphStudy"})
    {
        INFO(app);
        std::string help, h;
        REQUIRE(test::runProcess(app, {"-help"}, &help) == 0);
        REQUIRE(test::runProcess(app, {"-h"}, &h) == 0);
        CHECK_THAT(help, Catch::Contains("Usage: " + app));
        CHECK(h == help);
    }
}

TEST_CASE("summary.json records the version, the git revision and the command line, the .pvd "
          "shows short times",
          "[runRecord]")
{
    test::TempDir dir;
    const auto caseDir = test::copyTutorial("bar1D/dykaBar", dir.path());
    REQUIRE(test::runParticles(caseDir) == 0);
    // Outputs every 1e-4 s: the schedule sums the interval, 0.00030000000000000003 and on.
    REQUIRE(test::runSolver(caseDir, {"-set", "endTime=1e-3", "-set", "writeInterval=1e-4"}) ==
            0);

    std::ifstream summaryFile(caseDir / "postProcessing" / "summary.json");
    const nlohmann::json summary = nlohmann::json::parse(summaryFile);
    CHECK(summary.at("version") == projectVersion());
    CHECK(summary.at("gitRevision") == gitRevision());
    CHECK(summary.at("commandLine") ==
          "sphSolid -case " + caseDir.string() + " -set endTime=1e-3 -set writeInterval=1e-4");
    if (std::filesystem::exists(test::sourceDir() / ".git"))
    {
        CHECK(summary.at("gitRevision") != "unknown");
    }

    std::ifstream pvdFile(caseDir / "VTK" / "dykaBar.pvd");
    std::ostringstream pvd;
    pvd << pvdFile.rdbuf();
    const std::string text = pvd.str();
    std::vector<std::string> shown;
    const std::regex timestep("timestep=\"([^\"]*)\"");
    for (auto match = std::sregex_iterator(text.begin(), text.end(), timestep);
         match != std::sregex_iterator(); ++match)
    {
        shown.push_back((*match)[1]);
    }
    INFO(text);
    CHECK(shown == std::vector<std::string>{"0", "0.0001", "0.0002", "0.0003", "0.0004", "0.0005",
                                            "0.0006", "0.0007", "0.0008", "0.0009", "0.001"});
    // The exact times stay in the outputs (TimeValue, what a restart reads), a round-off from
    // the times shown.
    PvdSeries series(caseDir / "VTK" / "dykaBar.pvd");
    series.load();
    int inexact = 0;
    for (const auto& entry : series.entries())
    {
        const VtuData data = readVtu(caseDir / "VTK" / entry.file);
        const double exact = data.fieldData.at("TimeValue").values.at(0);
        CHECK(std::abs(exact - entry.time) <= seriesTimeTolerance * entry.time);
        inexact += exact != entry.time ? 1 : 0;
    }
    CHECK(inexact > 0); // else this case would not show the rounding
}
