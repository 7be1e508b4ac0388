// The geomaterials/columnCollapse tutorial shortened for CTest: the aluminium-rod column of Bui
// et al. (2008) at 1 cm spacing (200 particles) for the whole second, with the tutorial's scheme
// and the others of its README's table. For total-Lagrangian gradF, measured at this spacing:
// front 0.41 m, top 0.095 m, largest distance to the measured surface 1.2 cm; the deposit is at
// rest at the end. The bounds below are the measurement's (run-out 0.442 m, top 0.099 m) widened
// for the coarse spacing, and catch a collapse that does not happen (front ≈ 0.2 m), runs away
// (front > 0.6 m) or loses its shape.
#include "support/CaseRunner.hpp"

#include <algorithm>
#include <cmath>

using namespace sph;

namespace
{

// The tutorial at 1 cm to 1 s, one thread, with `settings` for sphSolid; returns its folder.
std::filesystem::path runCoarseCollapse(const test::TempDir& dir,
                                        const std::vector<std::string>& settings)
{
    const auto caseDir = test::copyTutorial("geomaterials/columnCollapse", dir.path());
    REQUIRE(test::runParticles(caseDir, {"-set", "column.spacing=0.01"}) == 0);
    std::vector<std::string> args{"-threads", "1", "-set", "writeInterval=0.5"};
    args.insert(args.end(), settings.begin(), settings.end());
    REQUIRE(test::runSolver(caseDir, args) == 0);
    return caseDir;
}

// The deposit of the tutorial's scheme (UL gradF elasticState, conserving weights, the
// close-pair energy): its height, every pair apart, the largest distance to the measured
// surface below `maxDistance` [m], and the moves' rises (measured, not assumed zero) below
// `maxRise` of the work gravity did.
void checkConservingDeposit(const std::filesystem::path& caseDir, double maxDistance,
                            double maxRise)
{
    const double top = test::summaryValue(caseDir, "functions/surface/top");
    const double distance = test::summaryValue(caseDir, "functions/surface/largestDistance");
    const double pair = test::summaryValue(caseDir, "functions/stability/minDistanceRatio");
    INFO("top " << top << " m, largest distance " << distance << " m, closest pair " << pair);
    CHECK(top > 0.09);
    CHECK(top < 0.1);
    CHECK(distance < maxDistance);
    CHECK(pair > 0.4);
    const auto energy = test::readTable(caseDir / "postProcessing" / "energy" / "energy.dat");
    const double gravity = energy.column("external").back();
    const double rises = energy.column("moveEnergyGain").back();
    INFO("moves' rises " << rises << " J/m of " << gravity);
    CHECK(rises > 0.0);
    CHECK(rises < maxRise * gravity);
}

} // namespace

TEST_CASE("column collapse, coarse: TL gradF deposits the column near the measured surface",
          "[geomaterials][columnCollapse]")
{
    test::TempDir dir;
    const auto caseDir = runCoarseCollapse(
        dir, {"-set", "formulation={ type totalLagrangian; }", "-set", "stabilisation={ type gradF; }",
              "-set", "impenetrability={ distance 0; }"});
    const double front = test::summaryValue(caseDir, "functions/surface/front");
    const double top = test::summaryValue(caseDir, "functions/surface/top");
    const double distance = test::summaryValue(caseDir, "functions/surface/largestDistance");
    INFO("front " << front << " m, top " << top << " m, largest distance " << distance << " m");
    CHECK(front > 0.35);
    CHECK(front < 0.55);
    CHECK(top > 0.09);
    CHECK(top < 0.1);
    CHECK(distance < 0.02);
    // At rest: the kinetic energy at the end is a small fraction of the work gravity did.
    const auto energy = test::readTable(caseDir / "postProcessing" / "energy" / "energy.dat");
    CHECK(energy.column("kinetic").back() < 1e-3 * energy.column("external").back());
}

TEST_CASE("column collapse, coarse: UL none completes, its time step does not collapse (P2.6)",
          "[geomaterials][columnCollapse][timeStep]")
{
    // With the total-F bound (P2.5) the step fell a hundredfold as the flow sheared the column
    // (5 mm: 1.8e-7 s at 0.55 s); with the stretch since the reference it stays near its start.
    // The front of this unstable scheme (stabilityMonitor: UNSTABLE) follows round-off: 0.595 m
    // before the plane-strain update in lanes (P13.4, 2026-11-29), 0.608 m after, 0.522 m with
    // `logarithm principalAxes` (the same law in another order); the bounds catch a column that
    // does not collapse (≈ 0.2 m) or runs away, not those digits.
    test::TempDir dir;
    const auto caseDir = runCoarseCollapse(
        dir, {"-set", "formulation={ type updatedLagrangian; }", "-set", "stabilisation={ type none; }",
              "-set", "impenetrability={ distance 0; }"});
    const double steps = test::summaryValue(caseDir, "steps");
    const double front = test::summaryValue(caseDir, "functions/surface/front");
    INFO(steps << " steps, front " << front << " m");
    CHECK(steps < 20000);
    CHECK(front > 0.35);
    CHECK(front < 0.65);
}

// The seed paper's method extended to plastic flow (docs/theory/gradF-plastic.md): UL gradF with
// samples that carry their elastic state completes the collapse the paper's kinematics cannot
// (it fails at 0.157 s at this spacing), deposits it near the measured surface, and the moves'
// energy is tabulated (referenceMoves): small against the work of gravity.
TEST_CASE("column collapse, coarse: UL gradF elasticState completes, near the measured surface",
          "[geomaterials][columnCollapse][gradF]")
{
    test::TempDir dir;
    const auto caseDir =
        runCoarseCollapse(dir, {"-set", "formulation={ type updatedLagrangian; }", "-set",
                                "stabilisation={ type gradF; plasticSamples elasticState; }",
                                "-set", "impenetrability={ distance 0; }", "-set",
                                "controlDict.functions.energy.referenceMoves=yes"});
    const double top = test::summaryValue(caseDir, "functions/surface/top");
    const double distance = test::summaryValue(caseDir, "functions/surface/largestDistance");
    INFO("top " << top << " m, largest distance " << distance << " m");
    CHECK(top > 0.09);
    CHECK(top < 0.1);
    CHECK(distance < 0.015);
    const auto energy = test::readTable(caseDir / "postProcessing" / "energy" / "energy.dat");
    const double gravity = energy.column("external").back();
    CHECK(energy.column("moveEnergyGain").back() > 0.0); // measured, not assumed zero
    CHECK(energy.column("moveEnergyGain").back() < 0.02 * gravity);
    CHECK(std::abs(energy.column("total").back() - energy.column("total").front()) <
          0.02 * gravity);
}

// The tutorial's scheme with the reference moved at every step (its default until 2026-11-27:
// UL gradF elasticState, the moves' energy weights that keep Π, the close-pair energy):
// completes near the measured surface with every pair apart, and the moves raise the energy 70
// times less than with the kernel's weights. Measured at 10 mm (2026-11-29, with the
// trapezoid's book (P9.7) and the weights' bracket of §G23): largest distance 1.09 cm, closest
// pair 0.50; the moves' rises 2.9e-5 J/m of the 7.6 J/m gravity does (3.7e-6; the kernel's
// weights: 0.19 J/m, 2.5e-2). Not round-off, as on the metal impact: where a particle's new
// support cannot reach the old energy the weights are widened and the residual is what is left
// (docs/theory/gradF-plastic.md §G9). (2.6e-3 J/m and 1.82 cm before the bracket's mend, most
// of it reachable energies the bracket missed; before 2026-11-28 1.14 cm and 5.9e-4 J/m, the
// weights of opened particles then chosen by round-off, (G22.3); one column of the loose slope
// decides the distance at this spacing, results.md §5.) That column follows round-off: the
// largest distance was 1.43 cm before the plane-strain update in lanes (P13.4, 2026-11-29), is
// 2.02 cm after it, and 0.95 cm with `logarithm principalAxes` (the same law in another order),
// the top 0.0979–0.0980 m and the closest pair 0.495 in all three: the bound is 2.5 cm here.
TEST_CASE("column collapse, coarse: UL gradF conserving, moved every step, keeps pairs apart, moves small",
          "[geomaterials][columnCollapse][gradF]")
{
    test::TempDir dir;
    const auto caseDir =
        runCoarseCollapse(dir, {"-set", "formulation.referenceUpdateInterval=1", "-set",
                                "controlDict.functions.energy.referenceMoves=yes"});
    checkConservingDeposit(caseDir, 0.025, 5e-5);
}

// The tutorial as it is (system/sphSchemes: the same scheme, the reference moved every fifth
// step; README, "Why this default"). Measured at 10 mm (2026-11-29, with the trapezoid's book
// (P9.7) and the weights' bracket of §G23): largest distance 0.90 cm, top 0.0980 m, closest
// pair 0.49, the moves' rises 2.6e-12 J/m of the 7.7 J/m gravity does, round-off (2.7e-3 J/m
// before the bracket's mend; the kernel's weights, 2.5e-2 of gravity). The distance's bound is
// the TL test's: at 10 mm the largest distance is decided by one column of the loose slope
// (results.md §5). The rises are round-off where every particle's bracket reaches the energy
// it must keep and a residual where one does not (§G9), which round-off decides: 6.4e-12 J/m
// before the plane-strain update in lanes (P13.4, 2026-11-29), 1.09e-5 J/m after it (1.4e-6 of
// gravity; largest distance 0.48 cm, top 0.0980 m, closest pair 0.49), 2.1e-6 J/m with
// `logarithm principalAxes`: the bound is 5e-6 of gravity.
TEST_CASE("column collapse, coarse: the tutorial's scheme, moved every fifth step, keeps pairs apart",
          "[geomaterials][columnCollapse][gradF]")
{
    test::TempDir dir;
    const auto caseDir =
        runCoarseCollapse(dir, {"-set", "controlDict.functions.energy.referenceMoves=yes"});
    checkConservingDeposit(caseDir, 0.02, 5e-6);
}

// The tutorial's scheme with the samples of opened particles taking their state at each move
// (openedSamples particle, docs/theory/gradF-plastic.md §G22). Measured at 10 mm (2026-11-29,
// with the trapezoid's book (P9.7) and the weights' bracket of §G23): largest distance 1.89 cm
// (the scheme without the rule: 0.90; 10 mm is a single run's lottery of pits, 0.98 cm on the
// code before, and not a spacing the 1 cm goal is for), closest pair 0.50; the moves change Π
// only by what they book as dissipated, so their rises are round-off (2.1e-12 J/m of the 7.7
// J/m gravity does), and the booked dissipation is real (the rule acted). The audit's error at
// 1 s is +0.21 J/m (2.7 %; without the rule +0.006): the kicks across the moves whose force the
// reset changed (§G23; `splitKick yes` removes them). The bounds are there so that a broken
// scheme (cm-deep pits everywhere, pairs, energy made at the moves) fails.
TEST_CASE("column collapse, coarse: the samples of opened particles take their state, the moves "
          "book what they dissipate",
          "[geomaterials][columnCollapse][gradF][opened]")
{
    test::TempDir dir;
    const auto caseDir =
        runCoarseCollapse(dir, {"-set", "controlDict.functions.energy.referenceMoves=yes", "-set",
                                "stabilisation.openedSamples=particle"});
    const double distance = test::summaryValue(caseDir, "functions/surface/largestDistance");
    const double pair = test::summaryValue(caseDir, "functions/stability/minDistanceRatio");
    INFO("largest distance " << distance << " m, closest pair " << pair);
    CHECK(distance < 0.025);
    CHECK(pair > 0.4);
    const auto energy = test::readTable(caseDir / "postProcessing" / "energy" / "energy.dat");
    const double gravity = energy.column("external").back();
    INFO("moves' rises " << energy.column("moveEnergyGain").back() << " J/m, audit error "
                         << energy.column("total").back() - energy.column("total").front()
                         << " J/m of " << gravity);
    CHECK(energy.column("moveEnergyGain").back() < 1e-10 * gravity);
    CHECK(std::abs(energy.column("total").back() - energy.column("total").front()) <
          0.05 * gravity);
}

// The 3D slab of geomaterials/columnCollapse3D (10 mm, 2 000 particles, between frictionless
// side walls) to 0.15 s, against the 2D tutorial at the same spacing and time: the mid-plane's
// surface is the plane-strain one while the column collapses. Measured (tutorial runs): at
// 0.05 s the two profiles agree to 0.4 mm, at 0.15 s the largest difference of their
// three-column means is 3.2 mm and the mean column difference 0.8 mm, the front near 0.26 m.
// A slab that is not plane strain fails: with rough side walls (friction 1) the mean column
// difference is 5.6 mm and the three-column one 1.75 cm.
TEST_CASE("column collapse 3D slab: the mid-plane collapses as the 2D plane-strain column",
          "[geomaterials][columnCollapse][3D]")
{
    test::TempDir dir;
    const std::vector<std::string> shortRun{"-threads", "1",
                                            "-set",     "endTime=0.15",
                                            "-set",     "writeInterval=0.15",
                                            "-set",     "functions.surface.writeInterval=0.15"};
    const auto slab = test::copyTutorial("geomaterials/columnCollapse3D", dir.path());
    REQUIRE(test::runParticles(slab) == 0);
    REQUIRE(test::runSolver(slab, shortRun) == 0);
    const auto plane = test::copyTutorial("geomaterials/columnCollapse", dir.path());
    REQUIRE(test::runParticles(plane, {"-set", "column.spacing=0.01"}) == 0);
    // The slab's scheme (TL gradF), in place of the 2D tutorial's own.
    std::vector<std::string> planeRun = shortRun;
    planeRun.insert(planeRun.end(), {"-set", "formulation={ type totalLagrangian; }", "-set",
                                     "stabilisation={ type gradF; }", "-set",
                                     "impenetrability={ distance 0; }"});
    REQUIRE(test::runSolver(plane, planeRun) == 0);
    const auto h3 =
        test::readTable(slab / "postProcessing" / "surface" / "surface_0.15.dat").column("height");
    const auto h2 =
        test::readTable(plane / "postProcessing" / "surface" / "surface_0.15.dat").column("height");
    REQUIRE(h3.size() > 20);
    REQUIRE(h2.size() > 20);
    const std::size_t columns = std::max(h3.size(), h2.size());
    const auto height = [](const std::vector<double>& h, std::size_t c)
    { return c < h.size() ? h[c] : 0.0; };
    const auto averaged = [&](const std::vector<double>& h, std::size_t c)
    {
        const std::size_t first = c == 0 ? 0 : c - 1;
        const std::size_t last = std::min(c + 1, columns - 1);
        double sum = 0.0;
        for (std::size_t k = first; k <= last; ++k)
        {
            sum += height(h, k);
        }
        return sum / static_cast<double>(last - first + 1);
    };
    double mean = 0.0;
    double largestAveraged = 0.0;
    for (std::size_t c = 0; c < columns; ++c)
    {
        mean += std::abs(height(h3, c) - height(h2, c));
        largestAveraged = std::max(largestAveraged, std::abs(averaged(h3, c) - averaged(h2, c)));
    }
    mean /= static_cast<double>(columns);
    const double front3 = test::summaryValue(slab, "functions/surface/front");
    const double front2 = test::summaryValue(plane, "functions/surface/front");
    INFO("mean column difference " << mean << " m, three-column " << largestAveraged
                                   << " m, fronts " << front3 << " / " << front2 << " m");
    CHECK(front3 > 0.23); // collapsing: the gate was at 0.2 m
    CHECK(std::abs(front3 - front2) < 0.01);
    CHECK(mean < 0.002);
    CHECK(largestAveraged < 0.005);
}
