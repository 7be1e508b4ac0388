// Rigid walls (constant/walls, walls/WallSet.hpp) on small blocks of stiff elastic material
// (c0 = 116 m/s, spacing 1 cm, 18 particles in 2D): Coulomb friction stops a sliding block
// after v²/(2 μ g), a frictionless bounce keeps the energy balance, a moving wall's work is the
// energy it gives, removeAt stops it, and the wallForce table carries the weight at rest.
#include "io/PvdSeries.hpp"
#include "solver/SolverCases.hpp"

#include <numeric>

using namespace sph;

namespace
{

constexpr double g = 9.81;
const std::string block2D = "block { type box; min (0 0); max (0.06 0.03); spacing 0.01; }";
const std::string floor2D = "floor { type plane; point (0 0); normal (0 1); ";

// The mean of component `d` of the displacement at the last output (the centroid's, since the
// particles of a box have equal masses).
double meanDisplacement(const std::filesystem::path& caseDir, int d)
{
    const VtuData last = test::lastOutput(caseDir);
    const VtuArray& u = last.pointData.at("displacement");
    double sum = 0.0;
    const std::size_t n = u.values.size() / static_cast<std::size_t>(u.components);
    for (std::size_t a = 0; a < n; ++a)
    {
        sum += u.values[a * static_cast<std::size_t>(u.components) + static_cast<std::size_t>(d)];
    }
    return sum / static_cast<double>(n);
}


test::Table table(const std::filesystem::path& caseDir, const std::string& name)
{
    return test::readTable(caseDir / "postProcessing" / name / (name + ".dat"));
}

} // namespace

TEST_CASE("walls: a block sliding with friction stops after v^2 / (2 mu g)", "[walls]")
{
    // 6x3 particles at 1 m/s along a floor with mu = 0.3 (0.170 m), then mu = 0.2 set from the
    // command line (0.255 m). The block chatters on the undamped penalty floor, but the mean
    // normal force is the weight (momentum balance), so the mean deceleration is mu g.
    test::TempDir dir;
    const auto folder = test::writeWallCase(
        dir.path() / "slide", 2, block2D,
        "gravity (0 -9.81);\nblock { material $stiff; velocity (1 0); }",
        floor2D + "friction 0.3; }", 0.4);
    REQUIRE(test::runParticles(folder) == 0);
    for (const double mu : {0.3, 0.2})
    {
        INFO("mu = " << mu);
        REQUIRE(test::runSolver(folder, {"-set", "walls.floor.friction=" + std::to_string(mu),
                                         "-set", "endTime=" + std::to_string(0.12 / mu)}) == 0);
        const double expected = 1.0 / (2.0 * mu * g);
        const double distance = meanDisplacement(folder, 0);
        INFO("distance " << distance << " expected " << expected);
        CHECK(std::abs(distance - expected) < 0.01 * expected);
        // Stopped (what momentum is left, 0.4 % of m v, is the chatter's), and the sliding
        // energy ½ m v² = 0.9 J/m went into friction work.
        CHECK(std::abs(table(folder, "energy").column("momentum_x").back()) < 1e-2 * 1.8);
        CHECK(test::summaryValue(folder, "functions/walls/floor_work") ==
              Approx(-0.9).epsilon(0.01));
        CHECK(std::abs(test::summaryValue(folder, "functions/energy/maxDrift")) < 1e-3);
    }
}

TEST_CASE("walls: a frictionless bounce keeps the energy balance", "[walls]")
{
    // Falling at 1 m/s from 1 cm onto the floor and back up. The balance error comes from the
    // contact starting and ending between time levels, ∝ (ω Δt)² = (courant hOverDx)²: the
    // largest |drift| is 1.5e-2 at courant 0.3, 1e-3 at 0.1 and 4e-4 at 0.05.
    test::TempDir dir;
    const auto folder = test::writeWallCase(
        dir.path() / "bounce", 2, "block { type box; min (0 0.01); max (0.06 0.04); spacing 0.01; }",
        "gravity (0 -9.81);\nblock { material $stiff; velocity (0 -1); }", floor2D + "}", 0.03,
        0.05);
    REQUIRE(test::runParticles(folder) == 0);
    REQUIRE(test::runSolver(folder) == 0);
    const auto energy = table(folder, "energy");
    CHECK(energy.column("momentum_y").back() > 1.0); // bounced: going up again (m = 1.8 kg/m)
    const auto potential = energy.column("wallPotential");
    CHECK(*std::max_element(potential.begin(), potential.end()) > 0.0);
    CHECK(test::summaryValue(folder, "functions/energy/maxDrift") < 1e-3);
}

TEST_CASE("walls: a moving wall's work is the energy it gives, removeAt stops it", "[walls]")
{
    // A wall at 0.5 m/s hits the block at rest (no gravity) and is removed at 0.5 ms, while it
    // still pushes (alone the block would leave the wall at about 1.3 ms).
    test::TempDir dir;
    const double removeAt = 5e-4;
    const auto folder = test::writeWallCase(
        dir.path() / "push", 2, block2D, "block { material $stiff; }",
        "pusher { type plane; point (0 0); normal (1 0); velocity (0.5 0); removeAt " +
            std::to_string(removeAt) + "; }",
        2e-3, 0.1);
    REQUIRE(test::runParticles(folder) == 0);
    REQUIRE(test::runSolver(folder) == 0);
    const auto energy = table(folder, "energy");
    const auto walls = table(folder, "walls");
    const auto time = walls.column("time");
    const auto force = walls.column("pusher_Fx");
    const auto work = walls.column("pusher_work");
    const auto momentum = energy.column("momentum_x");
    const std::size_t removed = static_cast<std::size_t>(
        std::find_if(time.begin(), time.end(), [&](double t) { return t >= removeAt; }) -
        time.begin());
    REQUIRE(removed + 1 < time.size());
    CHECK(force[removed - 1] > 1000.0); // still pushing just before
    for (std::size_t i = removed; i < time.size(); ++i)
    {
        INFO("t = " << time[i]);
        CHECK(force[i] == 0.0);
        CHECK(work[i] == work[removed]);
        CHECK(momentum[i] == Approx(momentum[removed]).epsilon(1e-12));
    }
    // The work equals the kinetic and strain energy gained (the stored wall potential left with
    // the wall): 0.2 % at courant 0.1.
    const double gained = energy.column("kinetic").back() + energy.column("strain").back();
    CHECK(work.back() > 0.3);
    CHECK(std::abs(work.back() - gained) < 5e-3 * work.back());
}

TEST_CASE("walls: at rest on a floor the wall carries the weight (2D and 3D)", "[walls]")
{
    // Released touching the floor, the block oscillates on the penalty springs; the time
    // average of the floor's force is the weight up to Δp/T (momentum balance), 1e-3 here.
    struct Case
    {
        int dimension;
        std::string particles;
        std::string walls;
        std::string gravity;
        std::string column;
        double weight;
    };
    const std::vector<Case> cases{
        {2, block2D, floor2D + "}", "(0 -9.81)", "floor_Fy", 1000 * 0.06 * 0.03 * g},
        {3, "block { type box; min (0 0 0); max (0.04 0.04 0.02); spacing 0.01; }",
         "floor { type plane; point (0 0 0); normal (0 0 2); }", "(0 0 -9.81)", "floor_Fz",
         1000 * 0.04 * 0.04 * 0.02 * g}};
    for (const Case& c : cases)
    {
        INFO(c.dimension << "D");
        test::TempDir dir;
        const auto folder = test::writeWallCase(dir.path() / "rest", c.dimension, c.particles,
                                                "gravity " + c.gravity + ";\nblock { material $stiff; }",
                                                c.walls, 0.02);
        REQUIRE(test::runParticles(folder) == 0);
        REQUIRE(test::runSolver(folder) == 0);
        const auto walls = table(folder, "walls");
        CHECK(test::timeAverage(walls, c.column) == Approx(c.weight).epsilon(1e-2));
        CHECK(std::abs(test::summaryValue(folder, "functions/energy/maxDrift")) < 1e-2);
    }
}
