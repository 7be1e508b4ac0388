// What the moves of the reference do to the energy (docs/theory/gradF-plastic.md §G19, §G20),
// on the zero-energy slam of tutorials/hardCases (two halves of a block thrown together, about
// fifty wave transits in 15 ms). The block is j2Plasticity that never yields, so that gradF's
// samples carry their elastic state (`plasticSamples elasticState`) while the material stays
// elastic, with the moves' weights that keep Π (`moveWeights conserving`, §G9): the moves make no
// energy of their own, and what remains is the work of the kicks across them.
//   - the kick as one (the default): each step's second half kick feels the moved reference's
//     force, and the energy grows, 0.19 of the initial in 15 ms (measured);
//   - the kick split at the moves (`splitKick yes`): every step is the leapfrog of one energy,
//     and the drift is the leapfrog's own, 5.5e-3 in 15 ms (measured), with a move at every
//     step or at every fifth.
#include "support/CaseRunner.hpp"

#include <iostream>

using namespace sph;

namespace
{

double slamDrift(const std::vector<std::string>& formulation)
{
    test::TempDir dir;
    const auto caseDir = test::copyTutorial("hardCases/zeroEnergyMode", dir.path());
    REQUIRE(test::runParticles(caseDir) == 0);
    std::vector<std::string> args{
        "-threads", "1", "-set", "writeInterval=1", "-set", "maxSteps=100000", "-set",
        "endTime=0.015", "-set",
        "bodies.block.material={ type j2Plasticity; E 1.0e6; nu 0.4; rho 1000; yieldStress 1e9; "
        "hardeningModulus 0; }",
        "-set", "stabilisation={ type gradF; plasticSamples elasticState; moveWeights conserving; }"};
    for (const auto& set : formulation)
    {
        args.insert(args.end(), {"-set", set});
    }
    REQUIRE(test::runSolver(caseDir, args) == 0);
    return test::summaryValue(caseDir, "functions/energy/maxDrift");
}

} // namespace

TEST_CASE("the slam with conserving moves: the kick split at the moves makes no energy, the "
          "kick as one does",
          "[moveEnergy][splitKick]")
{
    const double whole = slamDrift({"formulation={ type updatedLagrangian; }"});
    const double split = slamDrift({"formulation={ type updatedLagrangian; splitKick yes; }"});
    const double splitFifth =
        slamDrift({"formulation={ type updatedLagrangian; splitKick yes; referenceUpdateInterval 5; }"});
    std::cout << "slam, elasticState conserving, 15 ms: energy drift " << whole
              << " (kick as one), " << split << " (split), " << splitFifth
              << " (split, a move every fifth step)\n";
    CHECK(whole > 0.1);
    CHECK(split < 0.01);
    CHECK(splitFifth < 0.01);
}

namespace
{

// The moves of the slam to 5 ms at `courant`, the reference moved by strain (§G21).
long movesByStrain(const std::string& courant)
{
    test::TempDir dir;
    const auto caseDir = test::copyTutorial("hardCases/zeroEnergyMode", dir.path());
    REQUIRE(test::runParticles(caseDir) == 0);
    std::string output;
    REQUIRE(test::runProcess("sphSolid",
                             {"-case", caseDir.string(), "-threads", "1", "-set", "writeInterval=1",
                              "-set", "endTime=0.005", "-set", "courant=" + courant, "-set",
                              "formulation={ type updatedLagrangian; referenceUpdateStrain 0.03; "
                              "splitKick yes; }"},
                             &output) == 0);
    const std::string marker = "Reference   moved ";
    const auto at = output.find(marker);
    REQUIRE(at != std::string::npos);
    return std::stol(output.substr(at + marker.size()));
}

} // namespace

// A schedule in motion, not in steps: with the step four times smaller the reference moves
// about as often (measured: 103 and 131 times), where referenceUpdateInterval would move it four
// times as often, a different discretisation at each step size.
TEST_CASE("the reference moved by strain moves about as often at any step size",
          "[moveEnergy][referenceUpdateStrain]")
{
    const long coarse = movesByStrain("0.3");
    const long fine = movesByStrain("0.075");
    std::cout << "slam to 5 ms, referenceUpdateStrain 0.03: " << coarse << " moves at courant 0.3, "
              << fine << " at 0.075\n";
    CHECK(coarse > 20);
    CHECK(fine < 2 * coarse);
    CHECK(fine > coarse / 2);
}
