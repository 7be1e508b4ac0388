// The time step from the operator's measured largest frequency (docs/theory/timeStep.md): the
// measured frequency is the leapfrog's stability limit (T1.1) to a per cent; a probe that only
// reports leaves a run as it was, bit for bit (§T3: each evaluation is a function of the
// positions and the committed state, and what gradF sets aside around the probe is all its
// commit reads); `stepBound operator` starts with the wave-speed step and
// keeps the plastic impact stable at a Courant number where the wave-speed step lets it fail
// (§T2, §T4).
#include "core/Application.hpp"
#include "io/PvdSeries.hpp"
#include "io/VtuFile.hpp"
#include "solver/SolverCases.hpp"

using namespace sph;

namespace
{

// The plasticity2D/impact tutorial (1296 particles) in UL gradF elasticState, with `more`.
int runImpact(const std::filesystem::path& folder, const std::vector<std::string>& more)
{
    const auto caseDir = test::copyTutorial("plasticity2D/impact", folder);
    REQUIRE(test::runParticles(caseDir) == 0);
    std::vector<std::string> arguments{"-set", "formulation.type=updatedLagrangian", "-set",
                                       "stabilisation.type=gradF", "-set",
                                       "stabilisation.plasticSamples=elasticState"};
    arguments.insert(arguments.end(), more.begin(), more.end());
    return test::runSolver(caseDir, arguments);
}

// Every point and field-data array of `plain` is in `probed`, bit for bit; the probed run adds
// the probe's own state only (its mode, and field data).
void checkProbedIsPlain(const VtuData& plain, const VtuData& probed)
{
    REQUIRE(plain.points.size() == probed.points.size());
    CHECK(plain.points == probed.points);
    for (const auto& [name, array] : plain.pointData)
    {
        INFO(name);
        REQUIRE(probed.pointData.count(name));
        CHECK(array.values == probed.pointData.at(name).values);
    }
    for (const auto& [name, array] : plain.fieldData)
    {
        INFO(name);
        REQUIRE(probed.fieldData.count(name));
        CHECK(array.values == probed.fieldData.at(name).values);
    }
    CHECK(probed.pointData.size() == plain.pointData.size() + 1); // operatorMode
    CHECK(probed.fieldData.at("restart:operatorFrequency").values.at(0) > 0.0);
}

} // namespace

// The Dyka bar (1D, TL none, 40 particles) at a fixed step: ω̃ measured at the first level; a
// step with ω̃ Δt = 1.95 runs 500 steps, one with 2.05 blows up within a few dozen (T1.1). So the
// probe measures the limit itself, and the Courant numbers that give it are no guess.
TEST_CASE("the probed frequency is the leapfrog's stability limit", "[operatorProbe]")
{
    test::TempDir dir;
    const auto caseDir = test::copyTutorial("bar1D/dykaBar", dir.path());
    REQUIRE(test::runParticles(caseDir) == 0);
    const double courant = 0.01;
    REQUIRE(test::runSolver(caseDir, {"-set", "courant=0.01", "-set", "controlDict.maxSteps=1",
                                      "-set", "sphSchemes.timeIntegration={ probeInterval 1; }"}) == 0);
    const VtuData first = test::lastOutput(caseDir);
    const double omega = first.fieldData.at("restart:operatorFrequency").values.at(0);
    // ω̃ Δt per unit Courant number (Δt = courant h / c at F = I).
    const double perCourant = omega * first.fieldData.at("restart:firstDeltaT").values.at(0) / courant;
    const auto runAt = [&](double omegaDeltaT) {
        return test::runSolver(
            caseDir, {"-set", "courant=" + std::to_string(omegaDeltaT / perCourant), "-set",
                      "controlDict.timeStepUpdateInterval=0", "-set", "endTime=2e-2", "-set",
                      "writeInterval=1", "-set", "controlDict.functions.tipError.writeInterval=1",
                      "-set", "controlDict.functions.stability.writeInterval=1"});
    };
    CHECK(runAt(1.95) == 0);
    CHECK_THROWS_AS(runAt(2.05), NumericalFailure);
    // Once it follows the measured frequency, the diagnosis says so instead.
    CHECK_THROWS_WITH(test::runSolver(caseDir, {"-set", "courant=1.9", "-set",
                                                "sphSchemes.timeIntegration={ stepBound operator; }"}),
                      Catch::Contains("the step already follows"));
}

TEST_CASE("a probe that only reports leaves the run as it was, bit for bit", "[operatorProbe]")
{
    test::TempDir plain;
    test::TempDir probed;
    REQUIRE(runImpact(plain.path(), {"-set", "endTime=4e-6"}) == 0);
    REQUIRE(runImpact(probed.path(), {"-set", "endTime=4e-6", "-set",
                                      "sphSchemes.timeIntegration={ probeInterval 5; }"}) == 0);
    const VtuData a = test::lastOutput(plain.path() / "impact");
    const VtuData b = test::lastOutput(probed.path() / "impact");
    checkProbedIsPlain(a, b);
    const auto& alpha = a.pointData.at("plasticStrain").values;
    CHECK(*std::max_element(alpha.begin(), alpha.end()) > 0.01); // it flowed
}

// gradF sets its evaluation aside around the probe's (the samples' pending states and their
// dissipation) instead of evaluating the level again: what it sets aside must be all the commit
// reads. The column collapse's own scheme (UL gradF elasticState, conserving move weights, the
// close-pair energy; Drucker–Prager, yielding from the gate's removal) and TL gradF with the
// paper's per-sample history (j2Plasticity on the impact).
TEST_CASE("a probe that only reports leaves gradF's runs as they were, bit for bit",
          "[operatorProbe]")
{
    SECTION("the column collapse tutorial's scheme")
    {
        std::vector<VtuData> outputs;
        for (const std::string timeIntegration : {"{ }", "{ probeInterval 5; }"})
        {
            test::TempDir dir;
            const auto caseDir = test::copyTutorial("geomaterials/columnCollapse", dir.path());
            REQUIRE(test::runParticles(caseDir, {"-set", "column.spacing=0.01"}) == 0);
            REQUIRE(test::runSolver(caseDir, {"-set", "endTime=0.06", "-set",
                                              "sphSchemes.timeIntegration=" + timeIntegration}) == 0);
            outputs.push_back(test::lastOutput(caseDir));
        }
        checkProbedIsPlain(outputs[0], outputs[1]);
        const auto& alpha = outputs[0].pointData.at("plasticStrain").values;
        CHECK(*std::max_element(alpha.begin(), alpha.end()) > 0.01); // it flowed
    }
    SECTION("TL gradF, per-sample history")
    {
        std::vector<VtuData> outputs;
        for (const std::string timeIntegration : {"{ }", "{ probeInterval 5; }"})
        {
            test::TempDir dir;
            const auto caseDir = test::copyTutorial("plasticity2D/impact", dir.path());
            REQUIRE(test::runParticles(caseDir) == 0);
            REQUIRE(test::runSolver(caseDir, {"-set", "endTime=4e-6", "-set",
                                              "formulation.type=totalLagrangian", "-set",
                                              "stabilisation.type=gradF", "-set",
                                              "sphSchemes.timeIntegration=" + timeIntegration}) == 0);
            outputs.push_back(test::lastOutput(caseDir));
        }
        checkProbedIsPlain(outputs[0], outputs[1]);
    }
}

// At courant 0.5 the impact face's neighbourhoods stiffen the operator past the leapfrog's limit
// at about 16 µs with the wave-speed step (det f ≤ 0 of a stress sample); the measured step
// keeps the first level's ω Δt and completes. Both start with the same step.
TEST_CASE("stepBound operator keeps the plastic impact stable where the wave-speed step fails",
          "[operatorProbe]")
{
    test::TempDir waveSpeed;
    test::TempDir measured;
    const std::vector<std::string> common{"-set", "endTime=2e-5", "-set", "courant=0.5"};
    // The diagnosis names the step bound to try, and not once it is in use.
    CHECK_THROWS_WITH(runImpact(waveSpeed.path(), common),
                      Catch::Contains("timeIntegration { stepBound operator; }"));
    auto withOperator = common;
    withOperator.insert(withOperator.end(),
                        {"-set", "sphSchemes.timeIntegration={ stepBound operator; }"});
    REQUIRE(runImpact(measured.path(), withOperator) == 0);
    const VtuData first = readVtu(waveSpeed.path() / "impact" / "VTK" / "impact_0.vtu");
    const VtuData last = test::lastOutput(measured.path() / "impact");
    CHECK(last.fieldData.at("restart:firstDeltaT").values.at(0) ==
          first.fieldData.at("restart:deltaT").values.at(0));
    // κ = ω̃_0 Δt_0 of the first level: about 0.69 × 0.5/0.3 for this kernel (§T2).
    const double margin = last.fieldData.at("restart:operatorMargin").values.at(0);
    CHECK(margin > 0.9);
    CHECK(margin < 1.4);
    // The face stiffened: the step at the end is shorter than the first.
    CHECK(last.fieldData.at("restart:deltaT").values.at(0) <
          0.9 * last.fieldData.at("restart:firstDeltaT").values.at(0));
}

// A restart from an output written without the probe, with the probe now asked for: the missing
// restart data is named with what keeps it, not only as a missing array.
TEST_CASE("a restart that adds the probe says which setting changed", "[operatorProbe][restart]")
{
    test::TempDir dir;
    REQUIRE(runImpact(dir.path(), {"-set", "endTime=2e-6"}) == 0);
    CHECK_THROWS_WITH(
        test::runSolver(dir.path() / "impact",
                        {"-set", "formulation.type=updatedLagrangian", "-set",
                         "stabilisation.type=gradF", "-set",
                         "stabilisation.plasticSamples=elasticState", "-set", "endTime=4e-6",
                         "-set", "controlDict.startFrom=latestTime", "-set",
                         "sphSchemes.timeIntegration={ stepBound operator; }"}),
        Catch::Contains("restart:operatorMode' (the mode of the largest frequency") &&
            Catch::Contains("did not use the model that keeps it"));
}
