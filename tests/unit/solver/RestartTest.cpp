// `startFrom latestTime;` continues bit-identically to an uninterrupted run (issue 3): the final
// state and every function-object table are identical, in 1D total-Lagrangian and in 2D
// updated-Lagrangian + gradF (reference configuration and K restored between updates).
#include "io/PvdSeries.hpp"
#include "io/VtuFile.hpp"
#include "solver/SolverCases.hpp"

#include <fstream>
#include <sstream>

using namespace sph;

namespace
{

std::string fileText(const std::filesystem::path& file)
{
    std::ifstream in(file);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

VtuData lastOutput(const std::filesystem::path& caseDir)
{
    PvdSeries series(caseDir / "VTK" / (caseDir.filename().string() + ".pvd"));
    series.load();
    REQUIRE(!series.entries().empty());
    return readVtu(caseDir / "VTK" / series.entries().back().file);
}

void checkRestart(const std::filesystem::path& whole, const std::filesystem::path& split,
                  double endTime, double stopTime, const std::vector<std::string>& tables)
{
    REQUIRE(test::runParticles(whole) == 0);
    REQUIRE(test::runSolver(whole, {"-set", "endTime=" + std::to_string(endTime)}) == 0);
    REQUIRE(test::runParticles(split) == 0);
    REQUIRE(test::runSolver(split, {"-set", "endTime=" + std::to_string(stopTime)}) == 0);
    REQUIRE(test::runSolver(split, {"-set", "endTime=" + std::to_string(endTime), "-set",
                                    "controlDict.startFrom=latestTime"}) == 0);
    test::requireIdenticalState(lastOutput(whole), lastOutput(split));
    for (const auto& table : tables)
    {
        INFO(table);
        CHECK(fileText(whole / "postProcessing" / table / (table + ".dat")) ==
              fileText(split / "postProcessing" / table / (table + ".dat")));
    }
}

} // namespace

TEST_CASE("restart continues bit-identically: 1D total-Lagrangian Dyka bar", "[restart]")
{
    test::TempDir one;
    test::TempDir two;
    const auto whole = test::copyTutorial("bar1D/dykaBar", one.path());
    const auto split = test::copyTutorial("bar1D/dykaBar", two.path());
    for (const auto& dir : {whole, split})
    {
        test::setEntry(dir / "system" / "controlDict", "writeInterval", "2e-4");
    }
    checkRestart(whole, split, 1.5e-3, 0.7e-3, {"freeEnd", "energy", "tipError"});
}

TEST_CASE("restart continues bit-identically: 2D updated-Lagrangian gradF", "[restart]")
{
    test::TempDir one;
    test::TempDir two;
    const std::string schemes =
        "kernel { type cubicSpline; }\nformulation { type updatedLagrangian; "
        "referenceUpdateInterval 3; }\nstabilisation { type gradF; }\n";
    const auto whole = test::writeBlockCase(one.path() / "block", schemes, 1e-3, 1e-4);
    const auto split = test::writeBlockCase(two.path() / "block", schemes, 1e-3, 1e-4);
    checkRestart(whole, split, 1e-3, 0.45e-3, {"energy", "corner"});
}
