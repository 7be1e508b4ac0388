// The hard cases of tutorials/hardCases (issue 6), shortened, with the paper's scheme
// (updated-Lagrangian CSPH + gradient-of-F stabilisation): each asserts the case's own
// measure of "stable" from its README, as written and with the close-pair energy on
// (`impenetrability`, docs/theory/impenetrability.md: a new mechanism must keep every hard
// case stable). The full runs, with every scheme, are the studies in
// each case folder (sphStudy).
#include "support/CaseRunner.hpp"

#include <cmath>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

using namespace sph;

namespace
{

std::filesystem::path prepare(const test::TempDir& dir, const std::string& hardCase,
                              const std::vector<std::string>& particleSets = {})
{
    const auto caseDir = test::copyTutorial("hardCases/" + hardCase, dir.path());
    std::vector<std::string> args;
    for (const auto& set : particleSets)
    {
        args.insert(args.end(), {"-set", set});
    }
    REQUIRE(test::runParticles(caseDir, args) == 0);
    return caseDir;
}

// "" (the case as written) or the -set that adds the close-pair energy.
std::string mechanisms()
{
    return GENERATE(as<std::string>{}, "", "sphSchemes.impenetrability={ }");
}

std::vector<std::string> withSets(const std::vector<std::string>& sets,
                                  const std::string& mechanism = "")
{
    std::vector<std::string> args{"-set", "writeInterval=1"};
    if (!mechanism.empty())
    {
        args.insert(args.end(), {"-set", mechanism});
    }
    for (const auto& set : sets)
    {
        args.insert(args.end(), {"-set", set});
    }
    return args;
}

// A word of postProcessing/summary.json: functions/<object>/<key>.
std::string summaryText(const std::filesystem::path& caseDir, const std::string& object,
                        const std::string& key)
{
    std::ifstream in(caseDir / "postProcessing" / "summary.json");
    const nlohmann::json json = nlohmann::json::parse(in);
    return json.at("functions").at(object).at(key).get<std::string>();
}

} // namespace

TEST_CASE("hard case long bar: no creep over 50 ms", "[hardCases]")
{
    const std::string mechanism = mechanisms();
    INFO(mechanism);
    test::TempDir dir;
    const auto caseDir = prepare(dir, "longBar");
    REQUIRE(test::runSolver(caseDir, withSets({}, mechanism)) == 0);
    const double creep = test::summaryValue(caseDir, "functions/tipError/relativeMaxPeriodMean");
    const double drift = test::summaryValue(caseDir, "functions/energy/maxDrift");
    std::cout << "longBar: largest one-period mean of the tip / amplitude " << creep
              << ", energy drift " << drift << "\n";
    CHECK(std::abs(creep) < 0.02);
    CHECK(drift < 0.01);
}

TEST_CASE("hard case tensile instability: the noise does not grow", "[hardCases]")
{
    const std::string mechanism = mechanisms();
    INFO(mechanism);
    // 3000 of the 10 000 steps, with and without the noise; the perturbation is the difference.
    test::TempDir dir;
    const auto noisy = prepare(dir, "tensileInstability");
    REQUIRE(test::runSolver(noisy, withSets({"maxSteps=3000"}, mechanism)) == 0);
    test::TempDir cleanDir;
    const auto clean = prepare(cleanDir, "tensileInstability");
    REQUIRE(test::runSolver(clean,
                            withSets({"maxSteps=3000",
                                      "bodies.block.initialDisplacement.noise.amplitude=0"}, mechanism)) == 0);
    const auto a = test::readTable(noisy / "postProcessing/probe/probe.dat");
    const auto b = test::readTable(clean / "postProcessing/probe/probe.dat");
    double growth = 0.0;
    for (const char* column : {"displacement_x_0", "displacement_y_0", "displacement_x_1",
                               "displacement_y_1", "displacement_x_2", "displacement_y_2"})
    {
        const auto u = a.column(column);
        const auto v = b.column(column);
        REQUIRE(u.size() == v.size());
        for (std::size_t i = 0; i < u.size(); ++i)
        {
            growth = std::max(growth, std::abs(u[i] - v[i]) / 1e-9); // noise amplitude 1e-9 m
        }
    }
    const double closest = test::summaryValue(noisy, "functions/stability/minDistanceRatio");
    std::cout << "tensileInstability: perturbation / noise amplitude " << growth
              << ", closest neighbours " << closest << " spacings\n";
    CHECK(growth < 10.0);
    CHECK(closest > 1.0); // the stretched lattice stays a lattice (spacing 1.1)
}

TEST_CASE("hard case zero-energy mode: the seeded checkerboard stays bounded through a slam",
          "[hardCases]")
{
    const std::string mechanism = mechanisms();
    INFO(mechanism);
    test::TempDir dir;
    const auto caseDir = prepare(dir, "zeroEnergyMode");
    REQUIRE(test::runSolver(caseDir, withSets({"maxSteps=2500"}, mechanism)) == 0);
    const double indicator = test::summaryValue(caseDir, "functions/stability/maxIndicator");
    const double closest = test::summaryValue(caseDir, "functions/stability/minDistanceRatio");
    std::cout << "zeroEnergyMode: largest indicator " << indicator << ", closest neighbours "
              << closest << " spacings\n";
    CHECK(indicator < 0.1);
    CHECK(closest > 0.5);
    CHECK(summaryText(caseDir, "stability", "verdict") == "stable");
}

// A broken run says so (issue 12 item 15): the same slam without stabilisation, updated-
// Lagrangian, collapses the block; the run completes but the stability monitor's verdict in the
// log and in summary.json is "unstable", naming the deciding figure and its bound.
TEST_CASE("hard case zero-energy mode: without stabilisation the run ends with the verdict "
          "unstable",
          "[hardCases]")
{
    test::TempDir dir;
    const auto caseDir = prepare(dir, "zeroEnergyMode");
    std::vector<std::string> args{"-case", caseDir.string()};
    for (const auto& word : withSets({"maxSteps=2500", "formulation.type=updatedLagrangian",
                                      "stabilisation.type=none"}))
    {
        args.push_back(word);
    }
    std::string output;
    REQUIRE(test::runProcess("sphSolid", args, &output) == 0);
    CHECK(summaryText(caseDir, "stability", "verdict") == "unstable");
    CHECK_THAT(summaryText(caseDir, "stability", "verdictReason"),
               Catch::Contains("(stable >= 0.5, unstable < 0.1)"));
    CHECK_THAT(output, Catch::Contains("stability: verdict UNSTABLE: smallest neighbour distance"));
}

TEST_CASE("hard case fast rings: the rings bounce whole at 2.4 m/s", "[hardCases]")
{
    const std::string mechanism = mechanisms();
    INFO(mechanism);
    // 2 mm spacing, through the first contact and the largest deformation (about 16 ms).
    test::TempDir dir;
    const auto caseDir = prepare(dir, "fastRings", {"ringA.spacing=2e-3", "ringB.spacing=2e-3"});
    REQUIRE(test::runSolver(caseDir, withSets({"endTime=0.02"}, mechanism)) == 0);
    const double indicator = test::summaryValue(caseDir, "functions/stability/maxIndicator");
    const double closest = test::summaryValue(caseDir, "functions/stability/minDistanceRatio");
    const double drift = test::summaryValue(caseDir, "functions/energy/maxDrift");
    std::cout << "fastRings: largest indicator " << indicator << ", closest neighbours " << closest
              << " spacings, energy balance error " << drift << "\n";
    CHECK(indicator < 0.1);
    CHECK(closest > 0.5);
    CHECK(drift < 0.01);
}

TEST_CASE("hard case oscillating plate: three periods, no decay, coarse", "[hardCases]")
{
    const std::string mechanism = mechanisms();
    INFO(mechanism);
    // 5 mm spacing (4 particles across): T is 16 % long at this resolution (README: 1.5 % at
    // 1 mm); the test checks stability and the coarse result itself.
    test::TempDir dir;
    const auto caseDir = prepare(dir, "oscillatingPlate", {"plate.spacing=5e-3"});
    REQUIRE(test::runSolver(caseDir, withSets({}, mechanism)) == 0);
    const double periods = test::summaryValue(caseDir, "functions/tip/periods");
    const double period = test::summaryValue(caseDir, "functions/tip/meanPeriod");
    const double first = test::summaryValue(caseDir, "functions/tip/firstAmplitude");
    const double last = test::summaryValue(caseDir, "functions/tip/lastAmplitude");
    const double indicator = test::summaryValue(caseDir, "functions/stability/maxIndicator");
    std::cout << "oscillatingPlate: " << periods << " periods of " << period
              << " s, amplitude first " << first << " m, last " << last << " m, indicator "
              << indicator << "\n";
    CHECK(periods >= 3);
    CHECK(period == Approx(0.2955).epsilon(0.01));
    CHECK(last > 0.97 * first);
    CHECK(indicator < 0.1);
}

TEST_CASE("hard case large rotation: half a turn strains nothing", "[hardCases]")
{
    const std::string mechanism = mechanisms();
    INFO(mechanism);
    // 4 rad/s for half a revolution (the tutorial: 2 rad/s, three revolutions).
    test::TempDir dir;
    const auto caseDir = prepare(dir, "largeRotation");
    REQUIRE(test::runSolver(caseDir, withSets({"bodies.plate.initialVelocity.spin.omega=4",
                                               "endTime=0.7854"}, mechanism)) == 0);
    const double ratio = test::summaryValue(caseDir, "functions/energy/maxStrainOverKinetic");
    const double minJ = test::summaryValue(caseDir, "functions/stability/minJ");
    const double maxJ = test::summaryValue(caseDir, "functions/stability/maxJ");
    std::cout << "largeRotation: strain / kinetic energy " << ratio << ", det F in [" << minJ
              << ", " << maxJ << "]\n";
    CHECK(ratio < 1e-6);
    CHECK(std::abs(minJ - 1.0) < 1e-3);
    CHECK(std::abs(maxJ - 1.0) < 1e-3);
}

TEST_CASE("hard case twisting column: a coarse column twists and untwists whole", "[hardCases]")
{
    const std::string mechanism = mechanisms();
    INFO(mechanism);
    // 0.25 m spacing (4 x 4 x 24 particles, the lowest layer clamped) over 0.2 s: the top turns
    // about one revolution and back (the tutorial: 0.125 m over 0.5 s).
    test::TempDir dir;
    const auto caseDir = prepare(dir, "twistingColumn", {"column.spacing=0.25"});
    REQUIRE(test::runSolver(caseDir,
                            withSets({"endTime=0.2",
                                      "bodies.column.constraints.base.region.max=(1 1 0.25)"}, mechanism)) == 0);
    const double time = test::summaryValue(caseDir, "time");
    const double drift = test::summaryValue(caseDir, "functions/energy/maxDrift");
    const double closest = test::summaryValue(caseDir, "functions/stability/minDistanceRatio");
    const double minJ = test::summaryValue(caseDir, "functions/stability/minJ");
    std::cout << "twistingColumn: energy balance error " << drift << ", closest neighbours "
              << closest << " spacings, smallest det F " << minJ << "\n";
    CHECK(time >= 0.2);
    CHECK(drift < 0.05);
    CHECK(closest > 0.5);
    CHECK(minJ > 0.5);
}
