// Artificial viscosity in runs (sphSchemes artificialViscosity, artificialViscosity/): a block
// of stiff elastic material (c0 = 116 m/s, spacing 1 cm, 8x4 particles, no constraint, no
// gravity) whose halves run into each other at 5 m/s. With `monaghan` the momentum stays zero
// to round-off in both formulations, the viscosity dissipates (viscousWork < 0) and the energy
// balance with the viscousWork column closes, also for a block bouncing on a wall; with `none`
// the table has no such column.
#include "solver/SolverCases.hpp"

#include <fstream>

using namespace sph;

namespace
{

std::filesystem::path writeImpactCase(const std::filesystem::path& folder,
                                       const std::string& formulation,
                                       const std::string& viscosity)
{
    std::filesystem::create_directories(folder / "system");
    std::filesystem::create_directories(folder / "constant");
    std::ofstream(folder / "system" / "controlDict")
        << "endTime 2e-3;\ncourant 0.3;\nwriteInterval 2e-3;\n"
        << "functions\n{\n    energy { type energy; }\n}\n";
    std::ofstream(folder / "system" / "sphSchemes")
        << "dimension 2;\nkernel { type cubicSpline; hOverDx 1.5; }\nformulation { type "
        << formulation << "; }\nstabilisation { type gradF; }\n"
        << viscosity << "\n";
    std::ofstream(folder / "system" / "particlesDict")
        << "block { type box; min (0 0); max (0.08 0.04); spacing 0.01; }\n";
    std::ofstream(folder / "constant" / "bodies")
        << "block\n{\n    material { type linearElastic; E 1e7; nu 0.3; rho 1000; }\n"
        << "    initialVelocity\n    {\n"
        << "        left  { region { type box; min (0 0); max (0.04 0.04); } velocity (5 0); }\n"
        << "        right { region { type box; min (0.04 0); max (0.08 0.04); } velocity (-5 0); }\n"
        << "    }\n}\n";
    return folder;
}

test::Table energyTable(const std::filesystem::path& caseDir)
{
    return test::readTable(caseDir / "postProcessing" / "energy" / "energy.dat");
}

} // namespace

TEST_CASE("viscosity in a run: momentum conserved, dissipative, balance closes (TL, UL)",
          "[viscosity]")
{
    // The largest |drift| with the viscousWork column: TL 1.75e-3 at courant 0.3, 1.9e-4 at
    // 0.1 (and 1.7e-5 at 0.03): second order, so the audit misses no viscous work. UL 3.0e-3 at
    // 0.3: the scheme's own balance error (3.0e-2 at 0.3 without viscosity, 1.3e-2 at 0.03),
    // which the viscosity does not add to.
    struct Case
    {
        std::string formulation;
        double courant;
        double maxDrift;
    };
    for (const Case& c : {Case{"totalLagrangian", 0.3, 2.5e-3}, Case{"totalLagrangian", 0.1, 3e-4},
                          Case{"updatedLagrangian", 0.3, 5e-3}})
    {
        INFO(c.formulation << ", courant " << c.courant);
        test::TempDir dir;
        const auto folder = writeImpactCase(dir.path() / "impact", c.formulation,
                                            "artificialViscosity { type monaghan; alpha 1; beta 2; }");
        REQUIRE(test::runParticles(folder) == 0);
        REQUIRE(test::runSolver(folder, {"-set", "courant=" + std::to_string(c.courant)}) == 0);
        const auto energy = energyTable(folder);
        const auto work = energy.column("viscousWork");
        const auto kinetic = energy.column("kinetic");
        // Σ m |v| = 32 particles x 0.1 kg x 5 m/s = 16 kg m/s per metre; measured <= 1.3e-15.
        for (const std::string axis : {"momentum_x", "momentum_y"})
        {
            const auto momentum = energy.column(axis);
            const double largest = std::abs(*std::max_element(
                momentum.begin(), momentum.end(),
                [](double a, double b) { return std::abs(a) < std::abs(b); }));
            INFO(axis << ": largest |momentum| " << largest);
            CHECK(largest < 1e-12 * 16.0);
        }
        // The halves collide: the viscosity takes -27.4 J/m of the 40 J/m of kinetic energy.
        INFO("viscous work " << work.back() << ", kinetic " << kinetic.front() << " -> "
                             << kinetic.back());
        CHECK(work.front() == 0.0);
        CHECK(work.back() < -20.0);
        const double drift = test::summaryValue(folder, "functions/energy/maxDrift");
        INFO("max |drift| " << drift);
        CHECK(drift < c.maxDrift);
    }
}

TEST_CASE("viscosity none: no viscousWork column, same run as without the entry, monaghan "
          "bounds the time step",
          "[viscosity]")
{
    test::TempDir dir;
    const auto absent = writeImpactCase(dir.path() / "absent", "totalLagrangian", "");
    const auto none = writeImpactCase(dir.path() / "none", "totalLagrangian",
                                      "artificialViscosity { type none; }");
    for (const auto& folder : {absent, none})
    {
        REQUIRE(test::runParticles(folder) == 0);
        REQUIRE(test::runSolver(folder) == 0);
        CHECK(!energyTable(folder).hasColumn("viscousWork"));
        CHECK(energyTable(folder).hasColumn("drift"));
    }
    CHECK(energyTable(absent).column("total") == energyTable(none).column("total"));
    // Monaghan's bound c + 1.2 (alpha c + beta max mu) on the step: at alpha = 1 more than
    // twice the steps (116 against 52).
    const auto viscous = writeImpactCase(dir.path() / "viscous", "totalLagrangian",
                                         "artificialViscosity { type monaghan; alpha 1; beta 2; }");
    REQUIRE(test::runParticles(viscous) == 0);
    REQUIRE(test::runSolver(viscous) == 0);
    const double steps = test::summaryValue(none, "steps");
    const double viscousSteps = test::summaryValue(viscous, "steps");
    INFO("steps " << steps << " without viscosity, " << viscousSteps << " with");
    CHECK(viscousSteps > 2.0 * steps);
}

TEST_CASE("viscosity with walls: a block bouncing on a floor keeps the balance", "[viscosity]")
{
    // The frictionless bounce of WallTest.cpp (1 m/s onto the floor, courant 0.05) with
    // viscosity: the viscous forces act before the walls' in a^n. The viscosity takes 0.36 J/m
    // of the 0.9 J/m of kinetic energy and damps the chatter: largest |drift| 5.5e-5 (4e-4
    // without viscosity).
    test::TempDir dir;
    const auto folder = test::writeWallCase(
        dir.path() / "bounce", 2, "block { type box; min (0 0.01); max (0.06 0.04); spacing 0.01; }",
        "gravity (0 -9.81);\nblock { material $stiff; velocity (0 -1); }",
        "floor { type plane; point (0 0); normal (0 1); }", 0.03, 0.05);
    std::ofstream(folder / "system" / "sphSchemes", std::ios::app)
        << "artificialViscosity { type monaghan; alpha 1; beta 2; }\n";
    REQUIRE(test::runParticles(folder) == 0);
    REQUIRE(test::runSolver(folder) == 0);
    const auto energy = energyTable(folder);
    CHECK(energy.column("momentum_y").back() > 0.0); // bounced
    CHECK(energy.column("viscousWork").back() < 0.0);
    const double drift = test::summaryValue(folder, "functions/energy/maxDrift");
    INFO("max |drift| " << drift << ", viscous work " << energy.column("viscousWork").back());
    CHECK(drift < 2e-4);
}
