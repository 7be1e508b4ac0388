// When outputs are written (controlDict writeControl, issue 12 item 14): by default the steps
// before each output and function-object row time are shortened so that the level lands on it
// exactly (OpenFOAM's adjustableRunTime); `runTime` writes at the first level at or after it;
// `timeStep` every writeInterval steps.
#include "io/PvdSeries.hpp"
#include "io/VtuFile.hpp"
#include "solver/SolverCases.hpp"

#include <algorithm>
#include <cmath>

using namespace sph;

namespace
{

// The exact times of the outputs: their TimeValue (the .pvd shows them rounded to 1e-12).
std::vector<double> outputTimes(const std::filesystem::path& caseDir)
{
    PvdSeries series(caseDir / "VTK" / (caseDir.filename().string() + ".pvd"));
    series.load();
    std::vector<double> times;
    for (const auto& entry : series.entries())
    {
        const VtuData data = readVtu(caseDir / "VTK" / entry.file);
        times.push_back(data.fieldData.at("TimeValue").values.at(0));
    }
    return times;
}

// The Dyka bar to 1 ms with VTK every 1e-4 s and energy rows every 2.5e-5 s (Δt = 2.96e-7 s:
// neither is a multiple of the step).
std::filesystem::path runBar(const std::filesystem::path& into, std::vector<std::string> extra)
{
    const auto caseDir = test::copyTutorial("bar1D/dykaBar", into);
    REQUIRE(test::runParticles(caseDir) == 0);
    std::vector<std::string> args{"-set", "endTime=1e-3", "-set", "writeInterval=1e-4", "-set",
                                  "functions.energy.writeInterval=2.5e-5"};
    args.insert(args.end(), extra.begin(), extra.end());
    REQUIRE(test::runSolver(caseDir, args) == 0);
    return caseDir;
}

} // namespace

TEST_CASE("writeControl adjustableRunTime: outputs and rows land on their times exactly",
          "[schedule][output]")
{
    test::TempDir dir;
    const auto caseDir = runBar(dir.path(), {});
    const auto times = outputTimes(caseDir);
    REQUIRE(times.size() == 11);
    for (std::size_t k = 0; k < times.size(); ++k)
    {
        INFO("output " << k << " at " << times[k]);
        // The schedule's k-th multiple (accumulated 1e-4 steps: within a few ulps of k·1e-4).
        CHECK(std::abs(times[k] - 1e-4 * static_cast<double>(k)) <= 1e-18);
    }
    const auto energy = test::readTable(caseDir / "postProcessing" / "energy" / "energy.dat");
    const auto rowTimes = energy.column("time");
    REQUIRE(rowTimes.size() == 41);
    for (std::size_t k = 0; k < rowTimes.size(); ++k)
    {
        INFO("row " << k << " at " << rowTimes[k]);
        CHECK(std::abs(rowTimes[k] - 2.5e-5 * static_cast<double>(k)) <= 1e-12 * 2.5e-5); // %.12g
    }
    // The steps were shortened by a fraction of a step per interval, not split into slivers:
    // 1 ms at 2.96e-7 s is 3379.1 steps; landing on 40 row times costs at most one per interval.
    const double steps = test::summaryValue(caseDir, "steps");
    CHECK(steps >= 3380);
    CHECK(steps <= 3380 + 40);
    // The energy balance is as good as with the constant step.
    CHECK(std::abs(test::summaryValue(caseDir, "functions/energy/maxDrift")) < 1e-5);
}

TEST_CASE("writeControl runTime: the first level at or after each time, constant steps",
          "[schedule][output]")
{
    test::TempDir dir;
    const auto caseDir = runBar(dir.path(), {"-set", "controlDict.writeControl=runTime"});
    const auto times = outputTimes(caseDir);
    REQUIRE(times.size() == 11);
    for (std::size_t k = 1; k < times.size(); ++k)
    {
        const double wanted = 1e-4 * static_cast<double>(k);
        CHECK(times[k] >= wanted * (1 - 1e-12));
        CHECK(times[k] < wanted + 3e-7); // within one step of Δt = 2.96e-7 s
    }
    CHECK(times[1] != 1e-4); // 1e-4 is not a multiple of the step: not landed on
}

TEST_CASE("writeControl timeStep: an output every writeInterval steps", "[schedule][output]")
{
    test::TempDir dir;
    const auto caseDir = test::copyTutorial("bar1D/dykaBar", dir.path());
    REQUIRE(test::runParticles(caseDir) == 0);
    REQUIRE(test::runSolver(caseDir, {"-set", "endTime=1e-4", "-set", "writeInterval=100", "-set",
                                      "controlDict.writeControl=timeStep"}) == 0);
    const auto times = outputTimes(caseDir);
    // 1e-4 s is 338 steps of 2.96e-7 s: steps 0, 100, 200, 300 and the last level.
    REQUIRE(times.size() == 5);
    const double dt = times[1] / 100.0;
    CHECK(dt == Approx(2.9586e-7).epsilon(1e-3));
    CHECK(times[2] == Approx(200 * dt).epsilon(1e-12));
    CHECK(times[3] == Approx(300 * dt).epsilon(1e-12));
}

TEST_CASE("a function object's writeInterval 0 writes every step (snapshot too)",
          "[schedule][output]")
{
    test::TempDir dir;
    const auto caseDir = test::copyTutorial("bar1D/dykaBar", dir.path());
    REQUIRE(test::runParticles(caseDir) == 0);
    // endTime 3e-6 s takes 11 steps of 2.96e-7 s: 12 levels, each with its table.
    REQUIRE(test::runSolver(caseDir, {"-set", "endTime=3e-6", "-set",
                                      "functions.snap={type snapshot; writeInterval 0; "
                                      "fields (velocity);}"}) == 0);
    std::size_t files = 0;
    for (const auto& file : std::filesystem::directory_iterator(caseDir / "postProcessing/snap"))
    {
        files += file.path().extension() == ".dat" ? 1 : 0;
    }
    CHECK(files == 12);
}

TEST_CASE("purgeWrite keeps the last N outputs, and a restart continues from them",
          "[schedule][output]")
{
    test::TempDir dir;
    const auto caseDir = runBar(dir.path(), {"-set", "controlDict.purgeWrite=3"});
    const auto vtuFiles = [&]
    {
        std::vector<std::string> names;
        for (const auto& file : std::filesystem::directory_iterator(caseDir / "VTK"))
        {
            if (file.path().extension() == ".vtu")
            {
                names.push_back(file.path().filename().string());
            }
        }
        std::sort(names.begin(), names.end());
        return names;
    };
    CHECK(vtuFiles() == std::vector<std::string>{"dykaBar_10.vtu", "dykaBar_8.vtu", "dykaBar_9.vtu"});
    auto times = outputTimes(caseDir);
    REQUIRE(times.size() == 3);
    CHECK(times.front() == Approx(8e-4).epsilon(1e-12));
    REQUIRE(test::runSolver(caseDir, {"-set", "endTime=1.2e-3", "-set", "writeInterval=1e-4",
                                      "-set", "controlDict.purgeWrite=3", "-set",
                                      "controlDict.startFrom=latestTime"}) == 0);
    times = outputTimes(caseDir);
    REQUIRE(times.size() == 3);
    CHECK(times.front() == Approx(1e-3).epsilon(1e-12));
    CHECK(times.back() == Approx(1.2e-3).epsilon(1e-12));
    CHECK(vtuFiles() == std::vector<std::string>{"dykaBar_10.vtu", "dykaBar_11.vtu", "dykaBar_12.vtu"});
}
