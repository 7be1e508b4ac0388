// `startFrom latestTime;` continues bit-identically to an uninterrupted run (issue 3): the final
// state and every function-object table are identical, in 1D total-Lagrangian and in 2D
// updated-Lagrangian + gradF (reference configuration and K restored between updates).
#include "io/PvdSeries.hpp"
#include "io/VtuFile.hpp"
#include "solver/SolverCases.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

using namespace sph;

namespace
{

void checkRestart(const std::filesystem::path& whole, const std::filesystem::path& split,
                  double endTime, double stopTime, const std::vector<std::string>& tables,
                  const std::vector<std::string>& particleArgs = {})
{
    REQUIRE(test::runParticles(whole, particleArgs) == 0);
    REQUIRE(test::runSolver(whole, {"-set", "endTime=" + std::to_string(endTime)}) == 0);
    REQUIRE(test::runParticles(split, particleArgs) == 0);
    REQUIRE(test::runSolver(split, {"-set", "endTime=" + std::to_string(stopTime)}) == 0);
    REQUIRE(test::runSolver(split, {"-set", "endTime=" + std::to_string(endTime), "-set",
                                    "controlDict.startFrom=latestTime"}) == 0);
    test::requireIdenticalState(test::lastOutput(whole), test::lastOutput(split));
    for (const auto& table : tables)
    {
        INFO(table);
        CHECK(test::fileText(whole / "postProcessing" / table / (table + ".dat")) ==
              test::fileText(split / "postProcessing" / table / (table + ".dat")));
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

TEST_CASE("restart continues bit-identically from an output written in several pieces",
          "[restart]")
{
    // The flagship at half its spacing: 17 608 particles, so each output is streamed in three
    // pieces (io/VtuFile's writeVtuInPieces, 8192 particles each), which the restart reads
    // back as one set.
    test::TempDir one;
    test::TempDir two;
    const auto whole = test::copyTutorial("rings2D/collidingRings", one.path());
    const auto split = test::copyTutorial("rings2D/collidingRings", two.path());
    for (const auto& dir : {whole, split})
    {
        test::setEntry(dir / "system" / "controlDict", "writeInterval", "8e-6");
    }
    const std::vector<std::string> halfSpacing{"-set", "ringA.spacing=5e-4", "-set",
                                               "ringB.spacing=5e-4"};
    checkRestart(whole, split, 2.4e-5, 0.8e-5, {"energy", "extent"}, halfSpacing);
    REQUIRE(test::lastOutput(whole).pointCount() == 17608);
    REQUIRE(test::lastOutput(whole).pointCount() > 2 * defaultVtuPieceSize);
}

TEST_CASE("restart continues bit-identically: 2D updated-Lagrangian with viscosity",
          "[restart][viscosity]")
{
    // The viscous accelerations are recomputed from x^n, v^{n-1/2} and F^n of the output (they
    // bound the step of that level too); the viscous work is a run scalar of the energy audit.
    test::TempDir one;
    test::TempDir two;
    const std::string schemes =
        "kernel { type cubicSpline; }\nformulation { type updatedLagrangian; "
        "referenceUpdateInterval 3; }\nstabilisation { type gradF; }\n"
        "artificialViscosity { type monaghan; alpha 1; beta 2; }\n";
    const auto whole = test::writeBlockCase(one.path() / "block", schemes, 1e-3, 1e-4);
    const auto split = test::writeBlockCase(two.path() / "block", schemes, 1e-3, 1e-4);
    checkRestart(whole, split, 1e-3, 0.45e-3, {"energy", "corner"});
    CHECK(test::lastOutput(whole).fieldData.at("restart:viscousWork").values.at(0) < 0.0);
}

TEST_CASE("restart continues bit-identically: 2D block against walls", "[restart][walls]")
{
    // A block sliding on a floor with friction, pushed by a moving wall that is removed at
    // 0.5 ms; the split run is stopped after 10 of its 52 steps (maxSteps, t = 0.39 ms), in
    // contact with both walls, and continued from that output. The wall work is a run scalar of the
    // energy audit, the peak forces are the wallForce object's state.
    const auto write = [](const std::filesystem::path& folder) {
        return test::writeWallCase(
            folder, 2, "block { type box; min (0 0); max (0.06 0.03); spacing 0.01; }",
            "gravity (0 -9.81);\nblock { material $stiff; velocity (0.2 0); }",
            "floor { type plane; point (0 0); normal (0 1); friction 0.3; }\n"
            "pusher { type plane; point (0 0); normal (1 0); velocity (0.5 0); removeAt 5e-4; }",
            2e-3, 0.3);
    };
    test::TempDir one;
    test::TempDir two;
    const auto whole = write(one.path() / "walls");
    const auto split = write(two.path() / "walls");
    REQUIRE(test::runParticles(whole) == 0);
    REQUIRE(test::runSolver(whole) == 0);
    REQUIRE(test::runParticles(split) == 0);
    REQUIRE(test::runSolver(split, {"-set", "controlDict.maxSteps=10"}) == 0);
    REQUIRE(test::runSolver(split, {"-set", "controlDict.startFrom=latestTime"}) == 0);
    const VtuData last = test::lastOutput(whole);
    test::requireIdenticalState(last, test::lastOutput(split));
    CHECK(last.fieldData.at("restart:wallWork:floor").values.at(0) < 0.0);  // friction
    CHECK(last.fieldData.at("restart:wallWork:pusher").values.at(0) > 0.0); // pushed
    for (const std::string table : {"energy", "walls"})
    {
        INFO(table);
        CHECK(test::fileText(whole / "postProcessing" / table / (table + ".dat")) ==
              test::fileText(split / "postProcessing" / table / (table + ".dat")));
    }
    CHECK(test::summaryValue(whole, "functions/walls/pusher_peakNormalForce") ==
          test::summaryValue(split, "functions/walls/pusher_peakNormalForce"));
}

// The plasticity2D/impact tutorial (1296 particles), stopped after 60 steps (flowing
// plastically against the wall) and continued: the plastic history (Cp^-1, alpha, committed
// after each output; gradF's per-sample states), the dissipated energy and every table continue
// bit for bit. `extra`: further settings of both runs.
static void plasticImpactRestart(const std::vector<std::string>& extra)
{
    test::TempDir one;
    test::TempDir two;
    const auto whole = test::copyTutorial("plasticity2D/impact", one.path());
    const auto split = test::copyTutorial("plasticity2D/impact", two.path());
    std::vector<std::string> schemes{"-set", "formulation.type=updatedLagrangian", "-set",
                                     "stabilisation.type=gradF", "-set", "endTime=4e-6"};
    schemes.insert(schemes.end(), extra.begin(), extra.end());
    for (const auto& dir : {whole, split})
    {
        REQUIRE(test::runParticles(dir) == 0);
    }
    REQUIRE(test::runSolver(whole, schemes) == 0);
    auto first = schemes;
    first.insert(first.end(), {"-set", "controlDict.maxSteps=60"});
    REQUIRE(test::runSolver(split, first) == 0);
    auto second = schemes;
    second.insert(second.end(), {"-set", "controlDict.startFrom=latestTime"});
    REQUIRE(test::runSolver(split, second) == 0);
    const VtuData last = test::lastOutput(whole);
    test::requireIdenticalState(last, test::lastOutput(split));
    const auto& alpha = last.pointData.at("plasticStrain").values;
    CHECK(*std::max_element(alpha.begin(), alpha.end()) > 0.01); // it did flow
    CHECK(last.fieldData.at("restart:dissipatedEnergy").values.at(0) > 0.0);
    for (const std::string table : {"energy", "wall"})
    {
        INFO(table);
        CHECK(test::fileText(whole / "postProcessing" / table / (table + ".dat")) ==
              test::fileText(split / "postProcessing" / table / (table + ".dat")));
    }
}

TEST_CASE("restart continues bit-identically: 2D plastic impact, updated-Lagrangian gradF",
          "[restart][plasticity]")
{
    plasticImpactRestart({});
}

// The samples' states rebased at every move, F^r the dilation, and the moves' energy columns
// (restart scalars) continue bit for bit too.
TEST_CASE("restart continues bit-identically: 2D plastic impact, gradF elasticState with the "
          "moves' energy",
          "[restart][plasticity]")
{
    plasticImpactRestart({"-set", "stabilisation.plasticSamples=elasticState", "-set",
                          "controlDict.functions.energy.referenceMoves=yes"});
}

// The samples' energy weights chosen at every move (moveWeights conserving, §G9) are per-pair
// restart data, carried with the samples' states.
TEST_CASE("restart continues bit-identically: 2D plastic impact, gradF elasticState with "
          "conserving move weights",
          "[restart][plasticity]")
{
    plasticImpactRestart({"-set", "stabilisation.plasticSamples=elasticState", "-set",
                          "stabilisation.moveWeights=conserving"});
}

// The kick split at the moves (updatedLagrangian splitKick, gradF-plastic.md §G20), the
// reference moved every third step: the stop at step 60 falls on a move, where the velocity
// written is v^n, closed with the old reference's forces, and the restart opens from it.
TEST_CASE("restart continues bit-identically: 2D plastic impact, gradF elasticState with the "
          "kick split at the moves",
          "[restart][plasticity][splitKick]")
{
    plasticImpactRestart({"-set", "stabilisation.plasticSamples=elasticState", "-set",
                          "stabilisation.moveWeights=conserving", "-set",
                          "formulation={ type updatedLagrangian; referenceUpdateInterval 3; "
                          "splitKick yes; }"});
}

// Moves by the strain since the last one (referenceUpdateStrain, gradF-plastic.md §G21): the
// strain measured at the stop is restart data, so the restarted run moves at the same levels.
TEST_CASE("restart continues bit-identically: 2D plastic impact, gradF elasticState moving "
          "its reference by strain",
          "[restart][plasticity][referenceUpdateStrain]")
{
    plasticImpactRestart({"-set", "stabilisation.plasticSamples=elasticState", "-set",
                          "formulation={ type updatedLagrangian; referenceUpdateStrain 2e-4; "
                          "splitKick yes; }"});
}

// The samples of opened particles given their state at each move (openedSamples particle,
// gradF-plastic.md §G22), on the column collapse as the tutorial sets it up (a cohesionless
// druckerPrager, whose front opens): the reset samples and the dissipation the moves booked
// continue bit for bit; and the rule acted (the same run without it ends elsewhere).
TEST_CASE("restart continues bit-identically: the column collapse with the samples of opened "
          "particles taking their state",
          "[restart][plasticity][opened]")
{
    test::TempDir one;
    test::TempDir two;
    test::TempDir three;
    const auto whole = test::copyTutorial("geomaterials/columnCollapse", one.path());
    const auto split = test::copyTutorial("geomaterials/columnCollapse", two.path());
    const auto without = test::copyTutorial("geomaterials/columnCollapse", three.path());
    const std::vector<std::string> common{"-threads", "1", "-set", "endTime=0.06", "-set",
                                          "writeInterval=0.02", "-set", "functions={ energy { type "
                                          "energy; writeInterval 1e-3; referenceMoves yes; } }"};
    auto rule = common;
    rule.insert(rule.end(), {"-set", "stabilisation.openedSamples=particle"});
    for (const auto& dir : {whole, split, without})
    {
        REQUIRE(test::runParticles(dir) == 0);
    }
    REQUIRE(test::runSolver(whole, rule) == 0);
    REQUIRE(test::runSolver(without, common) == 0);
    auto first = rule;
    first.insert(first.end(), {"-set", "controlDict.maxSteps=352"}); // between two moves
    REQUIRE(test::runSolver(split, first) == 0);
    auto second = rule;
    second.insert(second.end(), {"-set", "controlDict.startFrom=latestTime"});
    REQUIRE(test::runSolver(split, second) == 0);
    const VtuData last = test::lastOutput(whole);
    test::requireIdenticalState(last, test::lastOutput(split));
    CHECK(test::fileText(whole / "postProcessing" / "energy" / "energy.dat") ==
          test::fileText(split / "postProcessing" / "energy" / "energy.dat"));
    CHECK(last.points != test::lastOutput(without).points);
}

// The step measured from the operator (docs/theory/timeStep.md): its kept mode (a particle
// field), margin and last frequency are restart data; the stop at step 60 falls between two
// probes (every 7 steps), so the restart keeps the step of the probe at 56.
TEST_CASE("restart continues bit-identically: 2D plastic impact, stepBound operator",
          "[restart][plasticity][operatorProbe]")
{
    plasticImpactRestart({"-set", "stabilisation.plasticSamples=elasticState", "-set",
                          "sphSchemes.timeIntegration={ stepBound operator; probeInterval 7; }"});
}

// An output of UL gradF elasticState (per-sample history, a run array) continued as TL none:
// the refusal names the array and that the settings differ, not "holds N values, not 1".
TEST_CASE("restart with another scheme names the history it does not keep", "[restart][errors]")
{
    test::TempDir dir;
    const auto caseDir = test::copyTutorial("plasticity2D/impact", dir.path());
    REQUIRE(test::runParticles(caseDir) == 0);
    REQUIRE(test::runSolver(caseDir, {"-set", "formulation.type=updatedLagrangian", "-set",
                                      "stabilisation.type=gradF", "-set",
                                      "stabilisation.plasticSamples=elasticState", "-set",
                                      "endTime=2e-6"}) == 0);
    CHECK_THROWS_WITH(test::runSolver(caseDir, {"-set", "endTime=4e-6", "-set",
                                                "controlDict.startFrom=latestTime"}),
                      Catch::Contains("the restart array 'restart:sampleHistory'") &&
                          Catch::Contains("other settings"));
}

// A .pvd that is a link to itself (a loop) gave "FATAL ERROR (internal) filesystem error";
// a restart now names the file and the reason (issue 31).
TEST_CASE("restart: a time series that links to itself is an input error", "[restart][errors]")
{
    test::TempDir dir;
    const auto caseDir = test::copyTutorial("bar1D/dykaBar", dir.path());
    REQUIRE(test::runParticles(caseDir) == 0);
    std::filesystem::create_directories(caseDir / "VTK");
    std::filesystem::create_symlink("dykaBar.pvd", caseDir / "VTK" / "dykaBar.pvd");
    std::string output;
    CHECK(test::runProcess("sphSolid", {"-case", caseDir.string(), "-set",
                                        "controlDict.startFrom=latestTime"},
                           &output) == 1);
    INFO(output);
    CHECK_THAT(output, Catch::Contains("FATAL INPUT ERROR") &&
                           Catch::Contains("dykaBar.pvd': too many levels of symbolic links"));
    CHECK_THAT(output, !Catch::Contains("internal"));
}
