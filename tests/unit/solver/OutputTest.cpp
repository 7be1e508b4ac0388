// Output: read back with VTK's own reader (array names, sizes, TimeValue); atomic writes (a
// killed run leaves a readable .pvd whose every file reads, and restarts from it).
#include "io/PvdSeries.hpp"
#include "io/VtuFile.hpp"
#include "solver/SolverCases.hpp"
#include "support/BackgroundProcess.hpp"

#include <signal.h>
#include <sys/wait.h>

#include <Eigen/LU>
#include <nlohmann/json.hpp>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

using namespace sph;

TEST_CASE("output reads back with VTK's reader: arrays, sizes, TimeValue", "[output]")
{
    test::TempDir dir;
    const auto caseDir = test::copyTutorial("bar1D/dykaBar", dir.path());
    REQUIRE(test::runParticles(caseDir) == 0);
    REQUIRE(test::runSolver(caseDir, {"-set", "endTime=1e-3", "-set", "writeInterval=2.5e-4"}) == 0);
    PvdSeries series(caseDir / "VTK" / "dykaBar.pvd");
    series.load();
    REQUIRE(series.entries().size() == 5); // t = 0, 2.5e-4, 5e-4, 7.5e-4 and the end
    double previous = -1.0;
    for (const auto& entry : series.entries())
    {
        const VtuData data = readVtu(caseDir / "VTK" / entry.file);
        REQUIRE(data.pointCount() == 40);
        CHECK(data.fieldData.at("TimeValue").values.at(0) ==
              Approx(entry.time).epsilon(seriesTimeTolerance)); // the .pvd rounds
        CHECK(entry.time > previous);
        previous = entry.time;
        // Display fields: physical names, 3-component vectors and 3×3 tensors of a 1D case,
        // double precision; the active attributes set.
        const std::map<std::string, int> expected{
            {"displacement", 3}, {"velocity", 3}, {"deformationGradient", 9},
            {"firstPiolaKirchhoffStress", 9}, {"cauchyStress", 9}, {"volumeRatio", 1},
            {"bodyId", 1}, {"fixed", 1}};
        for (const auto& [name, components] : expected)
        {
            INFO(name);
            REQUIRE(data.pointData.count(name));
            CHECK(data.pointData.at(name).components == components);
            CHECK(data.pointData.at(name).values.size() == 40u * components);
            CHECK(!data.pointData.at(name).readFromSingles);
        }
        CHECK(data.activeScalars == "volumeRatio");
        CHECK(data.activeVectors == "displacement");
        CHECK(data.activeTensors == "cauchyStress");
        const VtuArray& F = data.pointData.at("deformationGradient");
        CHECK(F.componentNames ==
              std::vector<std::string>{"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"});
        for (std::size_t a = 0; a < 40; ++a)
        {
            CHECK(F.values[9 * a + 4] == 1.0); // F_yy = F_zz = 1 in 1D (uniaxial strain)
            CHECK(F.values[9 * a + 8] == 1.0);
            CHECK(F.values[9 * a + 1] == 0.0);
            CHECK(data.pointData.at("velocity").values[3 * a + 1] == 0.0);
            CHECK(data.pointData.at("volumeRatio").values[a] == F.values[9 * a]); // J = F_xx
        }
        // Restart data apart: "restart:" arrays (the case's own D components), none displayed.
        for (const char* name : {"restart:initialPosition", "restart:velocityHalfStep",
                                 "restart:initialVolume", "restart:mass"})
        {
            INFO(name);
            REQUIRE(data.pointData.count(name));
            CHECK(data.pointData.at(name).components == 1);
        }
        for (const auto& [name, array] : data.pointData)
        {
            INFO(name);
            CHECK((expected.count(name) == 1 || name.rfind("restart:", 0) == 0));
        }
        CHECK(data.pointData.at("fixed").values.at(0) == 1.0);
        CHECK(data.stringFields.at("bodyNames") == std::vector<std::string>{"bar"});
    }
    CHECK(previous >= 1e-3);
    // summary.json is typed JSON: numbers are numbers (jq '.steps > 0' must work).
    std::ifstream summaryFile(caseDir / "postProcessing" / "summary.json");
    const nlohmann::json summary = nlohmann::json::parse(summaryFile);
    CHECK(summary.at("steps").is_number_integer());
    CHECK(summary.at("particles").get<int>() == 40);
    CHECK(summary.at("status") == "finished");
    CHECK(summary.at("functions").at("energy").at("maxDrift").is_number());
    CHECK(summary.at("functions").at("energy").at("maxDrift").get<double>() < 1e-3);
    // The free end moved and the fixed end did not.
    const VtuData last = readVtu(caseDir / "VTK" / series.entries().back().file);
    CHECK(last.pointData.at("displacement").values.at(0) == 0.0);
    CHECK(std::abs(last.pointData.at("displacement").values.at(3 * 39)) > 1e-4);
}

TEST_CASE("a killed run leaves a readable series that restarts", "[output]")
{
    test::TempDir dir;
    const auto caseDir = test::copyTutorial("bar1D/dykaBar", dir.path());
    REQUIRE(test::runParticles(caseDir, {"-set", "bar.n=640"}) == 0);
    test::BackgroundProcess solver(
        "sphSolid",
        {"-case", caseDir.string(), "-set", "writeInterval=2e-5", "-set", "endTime=1"},
        "/dev/null");
    // Let it write some outputs (the series is valid at every moment), then kill it without
    // warning while it keeps writing.
    PvdSeries series(caseDir / "VTK" / "dykaBar.pvd");
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < deadline)
    {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        REQUIRE_NOTHROW(series.load());
        if (series.entries().size() >= 8)
        {
            break;
        }
    }
    solver.signal(SIGKILL);
    REQUIRE(WIFSIGNALED(solver.wait()));

    REQUIRE_NOTHROW(series.load());
    REQUIRE(series.entries().size() >= 8);
    for (const auto& entry : series.entries())
    {
        const VtuData data = readVtu(caseDir / "VTK" / entry.file);
        CHECK(data.pointCount() == 640);
        CHECK(data.fieldData.at("TimeValue").values.at(0) ==
              Approx(entry.time).epsilon(seriesTimeTolerance)); // the .pvd rounds
    }
    // No temporary file is mistaken for output, and the run picks up where it was killed.
    const double killedAt = series.entries().back().time;
    std::ostringstream endTime;
    endTime.precision(17);
    endTime << killedAt + 2e-5;
    REQUIRE(test::runSolver(caseDir, {"-set", "controlDict.startFrom=latestTime", "-set",
                                      "endTime=" + endTime.str()}) == 0);
    series.load();
    CHECK(series.entries().back().time >= killedAt + 2e-5);
}

TEST_CASE("the derived display fields: Cauchy stress and volume ratio of a sheared block", "[output]")
{
    test::TempDir dir;
    const auto caseDir = test::writeBlockCase(dir.path() / "block", "kernel { type cubicSpline; }\n"
                                              "formulation { type totalLagrangian; }\n"
                                              "stabilisation { type none; }", 2e-4, 1e-4);
    REQUIRE(test::runParticles(caseDir) == 0);
    REQUIRE(test::runSolver(caseDir) == 0);
    PvdSeries series(caseDir / "VTK" / "block.pvd");
    series.load();
    const VtuData data = readVtu(caseDir / "VTK" / series.entries().back().file);
    const auto& F = data.pointData.at("deformationGradient").values;
    const auto& P = data.pointData.at("firstPiolaKirchhoffStress").values;
    const auto& sigma = data.pointData.at("cauchyStress").values;
    const auto& J = data.pointData.at("volumeRatio").values;
    double largestShear = 0.0;
    for (std::size_t a = 0; a < data.pointCount(); ++a)
    {
        Eigen::Matrix2d Fa;
        Eigen::Matrix2d Pa;
        Eigen::Matrix2d Sa;
        for (int i = 0; i < 2; ++i)
        {
            for (int j = 0; j < 2; ++j)
            {
                Fa(i, j) = F[9 * a + 3 * i + j];
                Pa(i, j) = P[9 * a + 3 * i + j];
                Sa(i, j) = sigma[9 * a + 3 * i + j];
            }
        }
        CHECK(J[a] == Approx(Fa.determinant()).epsilon(1e-14));
        const Eigen::Matrix2d expected = Pa * Fa.transpose() / Fa.determinant();
        CHECK((Sa - expected).norm() <= 1e-12 * expected.norm());
        // A hyperelastic Cauchy stress is symmetric (P F^T is; F^T P would not be).
        CHECK(std::abs(Sa(0, 1) - Sa(1, 0)) <= 1e-9 * Sa.norm());
        largestShear = std::max(largestShear, std::abs(Sa(0, 1)));
    }
    CHECK(largestShear > 0.0);
}
