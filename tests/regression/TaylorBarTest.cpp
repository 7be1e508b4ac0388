// The plasticity3D/taylorBar tutorial shortened for CTest: the copper Taylor bar at 1.6 mm
// (260 particles, four across the diameter) for the whole 80 µs. Total-Lagrangian CSPH without
// stabilisation is within 3 % of the finite-element references already at this spacing
// (measured: radius 7.05 mm, length 21.86 mm) and balances its energy; updated-Lagrangian
// gradF completes and mushrooms, spreading less (theory §P7: the kernel-length regularisation;
// docs/results.md §4).
#include "support/CaseRunner.hpp"

#include <cmath>

using namespace sph;

namespace
{

struct BarShape
{
    double radius = 0.0; // footprint: the largest distance of a centre from the axis + s/2
    double length = 0.0; // the extent of the centres along the axis + s
};

constexpr double spacing = 1.6e-3;

std::filesystem::path runTaylorBar(const std::filesystem::path& into,
                                   const std::vector<std::string>& schemes)
{
    const auto caseDir = test::copyTutorial("plasticity3D/taylorBar", into);
    REQUIRE(test::runParticles(caseDir, {"-set", "bar.spacing=1.6e-3", "-set",
                                         "bar.base=(0 0 0.8e-3)", "-set", "bar.length=31.6e-3"}) ==
            0);
    std::vector<std::string> args{"-threads", "1"};
    args.insert(args.end(), schemes.begin(), schemes.end());
    REQUIRE(test::runSolver(caseDir, args) == 0);
    return caseDir;
}

BarShape shapeOf(const std::filesystem::path& caseDir)
{
    BarShape shape;
    shape.radius = test::summaryValue(caseDir, "functions/shape/bar_final_max_x") + spacing / 2;
    shape.length = test::summaryValue(caseDir, "functions/shape/bar_final_max_z") -
                   test::summaryValue(caseDir, "functions/shape/bar_final_min_z") + spacing;
    return shape;
}

} // namespace

TEST_CASE("Taylor bar, coarse: TL none within 3 % of the finite-element references",
          "[plasticity][taylorBar]")
{
    test::TempDir dir;
    const auto caseDir = runTaylorBar(dir.path(), {"-set", "formulation.type=totalLagrangian",
                                                   "-set", "stabilisation.type=none"});
    const BarShape shape = shapeOf(caseDir);
    INFO("radius " << shape.radius << " m, length " << shape.length << " m");
    // References: radius 7.11–7.22 mm, length 21.42–21.48 mm (Simo 1992; Zienkiewicz et al.
    // 1998; Foulk et al. 2021); the goal is 3 % of that band.
    CHECK(shape.radius > 0.97 * 7.11e-3);
    CHECK(shape.radius < 1.03 * 7.22e-3);
    CHECK(shape.length > 0.97 * 21.42e-3);
    CHECK(shape.length < 1.03 * 21.48e-3);
    // The balance closes (measured 1.6e-3) and nearly all the kinetic energy became plastic
    // work (228 of 245 J).
    CHECK(std::abs(test::summaryValue(caseDir, "functions/energy/maxDrift")) < 1e-2);
    const auto energy = test::readTable(caseDir / "postProcessing/energy/energy.dat");
    CHECK(energy.column("dissipated").back() > 0.85 * energy.column("kinetic").front());
    CHECK(energy.column("kinetic").back() < 0.01 * energy.column("kinetic").front());
}

TEST_CASE("Taylor bar, coarse: UL gradF completes and mushrooms", "[plasticity][taylorBar]")
{
    test::TempDir dir;
    const auto caseDir = runTaylorBar(dir.path(), {"-set", "formulation.type=updatedLagrangian",
                                                   "-set", "stabilisation.type=gradF"});
    const BarShape shape = shapeOf(caseDir);
    INFO("radius " << shape.radius << " m, length " << shape.length << " m");
    // Measured 5.56 mm and 20.4 mm: the foot spreads to 1.7 R0 and the bar shortens by 37 %.
    CHECK(shape.radius > 1.5 * 3.2e-3);
    CHECK(shape.length < 0.75 * 32.4e-3);
    // Its energy error comes from the reference moves (theory §P7; measured 0.059 here).
    CHECK(std::abs(test::summaryValue(caseDir, "functions/energy/maxDrift")) < 0.1);
}
