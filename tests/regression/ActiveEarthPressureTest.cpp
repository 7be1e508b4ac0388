// The geomaterials/activeEarthPressure tutorial shortened for CTest: the smooth retaining wall
// moved 5 mm away from 1 m of cohesionless soil (druckerPrager, phi = psi = 30 degrees,
// geostatic start) at the tutorial's 1 mm/s, TL none, H/20 (600 particles); a few seconds.
// Rankine: K_a = (1 - sin phi)/(1 + sin phi) = 1/3, the wedge's boundary at 45 + phi/2 = 60
// degrees from the horizontal through the heel. Measured at this spacing (tutorial README,
// docs/results.md §7): K = 0.3106 over wall displacement 2-5 mm (-6.8 %; H/10 -13.9 %, H/40
// and H/80 closer), the band's centre line at 62.3 degrees. The bands below hold those figures
// and fail a thrust that stays at rest (K0 = 0.5), one that falls far below Rankine's (the
// stabilised schemes: gradF 0.25, hourglass 0.04-0.2 at this spacing) or a wedge at another
// angle (psi = 0: 57.0 degrees; a failure along the wall or the floor: none).
#include "support/CaseRunner.hpp"

#include <algorithm>
#include <cmath>
#include <map>

using namespace sph;

namespace
{

const double degree = M_PI / 180.0;
const double rankine = (1.0 - std::sin(30 * degree)) / (1.0 + std::sin(30 * degree));

struct Wall
{
    double plateau = 0.0; // mean K over wall displacement 2-5 mm
    double atRest = 0.0;  // K in the first row after t = 0
    double floor = 0.0;   // the floor's mean vertical reaction over the plateau / the weight
    double wedge = 0.0;   // the shear band's angle from the horizontal [degrees]
};

// The tutorial at H/20 with `settings` for sphSolid: its thrust coefficient and the shear band
// (the centre line x(y) of the largest plastic strain in each row within x <= H, rows between
// 0.2 H and 0.8 H, fitted by least squares; thrust.py's estimator).
Wall runWall(const std::vector<std::string>& settings)
{
    test::TempDir dir;
    const auto caseDir = test::copyTutorial("geomaterials/activeEarthPressure", dir.path());
    REQUIRE(test::runParticles(caseDir) == 0);
    std::vector<std::string> args{"-threads", "1"};
    args.insert(args.end(), settings.begin(), settings.end());
    REQUIRE(test::runSolver(caseDir, args) == 0);
    // The tutorial's values: v = 1 mm/s, rho = 2000 kg/m^3, g = 9.81 m/s^2, H = 1 m, L = 1.5 m.
    const double v = 1e-3;
    const double gammaH2 = 2000 * 9.81 * 1.0;
    const double weight = gammaH2 * 1.5;
    const auto walls = test::readTable(caseDir / "postProcessing" / "walls" / "walls.dat");
    const auto time = walls.column("time");
    const auto thrust = walls.column("retainer_Fx");
    const auto floor = walls.column("floor_Fy");
    Wall result;
    REQUIRE(time.size() > 2);
    result.atRest = 2.0 * thrust[1] / gammaH2;
    int rows = 0;
    for (std::size_t i = 0; i < time.size(); ++i)
    {
        const double travel = 1e3 * v * time[i];
        if (travel >= 2.0 && travel <= 5.0)
        {
            result.plateau += 2.0 * thrust[i] / gammaH2;
            result.floor += floor[i] / weight;
            ++rows;
        }
    }
    REQUIRE(rows > 200);
    result.plateau /= rows;
    result.floor /= rows;

    const auto particles =
        test::readTable(caseDir / "postProcessing" / "particles" / "particles_5.dat");
    const auto x = particles.column("x");
    const auto y = particles.column("y");
    const auto strain = particles.column("plasticStrain");
    const double spacing = 0.05;
    std::map<long, std::pair<double, double>> band; // row -> (largest strain, its x)
    for (std::size_t a = 0; a < x.size(); ++a)
    {
        if (x[a] > 1.0)
        {
            continue;
        }
        auto& [largest, at] = band[std::lround(y[a] / spacing - 0.5)];
        if (strain[a] > largest)
        {
            largest = strain[a];
            at = x[a];
        }
    }
    std::vector<std::pair<double, double>> line; // (y, x) of the band's centre
    for (const auto& [row, peak] : band)
    {
        const double yRow = (static_cast<double>(row) + 0.5) * spacing;
        if (yRow >= 0.2 && yRow <= 0.8 && peak.first > 1e-3)
        {
            line.emplace_back(yRow, peak.second);
        }
    }
    REQUIRE(line.size() >= 6);
    double my = 0.0;
    double mx = 0.0;
    for (const auto& [yb, xb] : line)
    {
        my += yb;
        mx += xb;
    }
    my /= static_cast<double>(line.size());
    mx /= static_cast<double>(line.size());
    double sxy = 0.0;
    double syy = 0.0;
    for (const auto& [yb, xb] : line)
    {
        sxy += (yb - my) * (xb - mx);
        syy += (yb - my) * (yb - my);
    }
    result.wedge = std::atan2(1.0, sxy / syy) / degree;
    return result;
}

} // namespace

TEST_CASE("Active earth pressure, coarse: the thrust falls from K0 to just under Rankine's K_a, "
          "the wedge at 45 + phi/2",
          "[geomaterials][activeEarthPressure]")
{
    const Wall wall = runWall({});
    INFO("K at rest " << wall.atRest << ", plateau " << wall.plateau << " (Rankine " << rankine
                      << "), floor / weight " << wall.floor << ", wedge " << wall.wedge
                      << " degrees");
    CHECK(wall.atRest > 0.45); // the geostatic start: K0 = 1 - sin 30 = 0.5
    CHECK(wall.plateau > 0.9 * rankine);
    CHECK(wall.plateau < rankine);
    CHECK(std::abs(wall.floor - 1.0) < 0.01); // quasi-static: the floor carries the weight
    CHECK(wall.wedge > 57.0);
    CHECK(wall.wedge < 65.0);
}

TEST_CASE("Active earth pressure, coarse: with psi = 0 the thrust is larger and the band less "
          "steep than Rankine's",
          "[geomaterials][activeEarthPressure]")
{
    const Wall wall = runWall({"-set", "bodies.soil.material.dilatancyAngle=0"});
    INFO("psi 0: plateau " << wall.plateau << " (Rankine " << rankine << "), wedge " << wall.wedge
                           << " degrees");
    // At this spacing between Rankine's 1/3 and Davis's 0.382 (docs/theory/geotechnics.md
    // §E1), above the associative run's, and the band between Arthur's 52.5 and Coulomb's 60
    // degrees. Measured: 0.3584 and 57.0 degrees (the associative run: 0.3106 and 62.3). A
    // regression at H/20 only: the psi = 0 thrust rises at every refinement (0.397 at H/40,
    // 0.424 at H/80; the tutorial's README), it does not converge.
    CHECK(wall.plateau > rankine);
    CHECK(wall.plateau < 0.382);
    CHECK(wall.wedge > 50.0);
    CHECK(wall.wedge < 60.0);
}
