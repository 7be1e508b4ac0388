// A column of Drucker–Prager soil at rest under gravity in a box (issue 17, item 3): the
// `geostatic` initial stress (docs/theory/plasticity.md §P10) starts it in equilibrium, so the
// floor carries the weight ρ g H L, the side walls the lateral thrust K0 ρ g H²/2, and the
// column does not move; a restart continues the pre-stressed run bit for bit; the initial
// stress's input errors are in tests/errors/initialStress*.
#include "io/PvdSeries.hpp"
#include "solver/SolverCases.hpp"

#include <cmath>
#include <numbers>

using namespace sph;

namespace
{

constexpr double rho = 2650.0;
constexpr double g = 9.81;
constexpr double height = 0.1;
constexpr double length = 0.2;
constexpr double spacing = 0.01;
const double K0 = 1.0 - std::sin(19.8 * std::numbers::pi / 180.0); // Jaky, the default

// The column collapse of tutorials/geomaterials/columnCollapse behind its gate, 20 x 10 particles.
std::filesystem::path writeColumnCase(const std::filesystem::path& folder,
                                      const std::string& formulation, const std::string& scheme,
                                      double endTime, double writeInterval)
{
    std::filesystem::create_directories(folder / "system");
    std::filesystem::create_directories(folder / "constant");
    std::ofstream(folder / "system" / "controlDict")
        << "endTime " << endTime << ";\ncourant 0.3;\nwriteInterval " << writeInterval << ";\n"
        << "functions\n{\n    walls { type wallForce; }\n"
        << "    extent { type extent; }\n}\n";
    std::ofstream(folder / "system" / "sphSchemes")
        << "dimension 2;\nkernel { type cubicSpline; hOverDx 1.5; }\nformulation { type "
        << formulation << "; }\nstabilisation { type " << scheme << "; }\n";
    std::ofstream(folder / "system" / "particlesDict")
        << "column { type box; min (0 0); max (" << length << " " << height << "); spacing "
        << spacing << "; }\n";
    std::ofstream(folder / "constant" / "bodies")
        << "gravity (0 -9.81);\ncolumn\n{\n    material { type druckerPrager; E 0.84e6; nu 0.3; "
           "rho 2650; frictionAngle 19.8; }\n    initialStress { type geostatic; }\n}\n";
    std::ofstream(folder / "constant" / "walls")
        << "floor { type plane; point (0 0); normal (0 1); friction 0.36; }\n"
        << "back { type plane; point (0 0); normal (1 0); }\n"
        << "gate { type plane; point (" << length << " 0); normal (-1 0); }\n";
    return folder;
}


VtuData output(const std::filesystem::path& caseDir, std::size_t index)
{
    PvdSeries series(caseDir / "VTK" / (caseDir.filename().string() + ".pvd"));
    series.load();
    REQUIRE(series.entries().size() > index);
    return readVtu(caseDir / "VTK" / series.entries().at(index).file);
}

} // namespace

TEST_CASE("geostatic: the initial stress is rho g depth vertically and K0 times it sideways",
          "[geostatic][plasticity]")
{
    test::TempDir dir;
    const auto caseDir = writeColumnCase(dir.path() / "column", "totalLagrangian", "none", 1e-3, 1e-3);
    REQUIRE(test::runParticles(caseDir) == 0);
    REQUIRE(test::runSolver(caseDir) == 0);
    const VtuData first = output(caseDir, 0); // (the output shows the in-plane stress; zz:
                                               // GeostaticMaterialTest)
    const VtuArray& sigma = first.pointData.at("cauchyStress");
    const auto n = static_cast<std::size_t>(sigma.components);
    REQUIRE(n == 9);
    for (std::size_t a = 0; a < first.pointCount(); ++a)
    {
        const double y = first.points[3 * a + 1];
        const double vertical = -rho * g * (height - y); // the surface half a spacing above the top row
        INFO("particle " << a << " at y = " << y);
        CHECK(sigma.values[a * n + 4] == Approx(vertical).epsilon(1e-9));
        CHECK(sigma.values[a * n + 0] == Approx(K0 * vertical).epsilon(1e-9));
        CHECK(std::abs(sigma.values[a * n + 1]) < 1e-9 * rho * g * height);
    }
}

TEST_CASE("geostatic: a column at rest in a box carries its weight and does not move",
          "[geostatic][plasticity][walls]")
{
    // Measured at 1 cm spacing over 0.1 s (docs/theory/plasticity.md §P10): the floor's mean
    // force is the weight to 0.2 % (what the start's small imbalance leaves, Δp/T); the gate's
    // is K0 ρ g H²/2 to 11 % (none), 5 % (gradF), and converges with the spacing (none: 3.8 %
    // at 5 mm, 1.2 % at 2.5 mm); the largest displacement stays below 0.01 spacing.
    const double weight = rho * g * height * length;
    const double thrust = K0 * rho * g * height * height / 2.0;
    struct Case
    {
        std::string formulation;
        std::string scheme;
        double thrustTolerance;
    };
    for (const Case& c : {Case{"totalLagrangian", "none", 0.12}, Case{"updatedLagrangian", "none", 0.12},
                          Case{"updatedLagrangian", "gradF", 0.06}})
    {
        INFO(c.formulation << " " << c.scheme);
        test::TempDir dir;
        const auto caseDir = writeColumnCase(dir.path() / "column", c.formulation, c.scheme, 0.1, 0.1);
        REQUIRE(test::runParticles(caseDir) == 0);
        REQUIRE(test::runSolver(caseDir) == 0);
        const auto walls = test::readTable(caseDir / "postProcessing" / "walls" / "walls.dat");
        CHECK(test::timeAverage(walls, "floor_Fy") == Approx(weight).epsilon(5e-3));
        CHECK(-test::timeAverage(walls, "gate_Fx") == Approx(thrust).epsilon(c.thrustTolerance));
        CHECK(test::timeAverage(walls, "back_Fx") == Approx(thrust).epsilon(c.thrustTolerance));
        const auto extent = test::readTable(caseDir / "postProcessing" / "extent" / "extent.dat");
        double largest = 0.0;
        for (const double u : extent.column("column_maxDisplacement"))
        {
            largest = std::max(largest, u);
        }
        CHECK(largest < 0.01 * spacing);
    }
}

TEST_CASE("geostatic: a restart continues the pre-stressed column bit for bit",
          "[geostatic][plasticity][restart]")
{
    test::TempDir dir;
    const auto whole = writeColumnCase(dir.path() / "whole", "updatedLagrangian", "gradF", 4e-3, 2e-3);
    const auto split = writeColumnCase(dir.path() / "split", "updatedLagrangian", "gradF", 4e-3, 2e-3);
    REQUIRE(test::runParticles(whole) == 0);
    REQUIRE(test::runParticles(split) == 0);
    REQUIRE(test::runSolver(whole) == 0);
    REQUIRE(test::runSolver(split, {"-set", "endTime=2e-3"}) == 0);
    REQUIRE(test::runSolver(split, {"-set", "controlDict.startFrom=latestTime"}) == 0);
    test::requireIdenticalState(output(whole, 2), output(split, 2));
}
