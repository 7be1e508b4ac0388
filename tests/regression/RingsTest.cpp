// The colliding rings tutorial (seed §3.2, spec §11.2), coarse (Δx = 2 mm, 1120 particles) and
// shortened to a few ms past first contact (from about 6 ms), under CTest:
//   - no particle of one ring inside the other (the closest pair across the rings stays well
//     apart at every output),
//   - energy balance kinetic + strain - contact work within 2 %,
//   - total linear momentum zero to round-off,
//   - the two rings' largest y-displacements equal within 1 % (they are mirror images).
#include "io/PvdSeries.hpp"
#include "io/VtuFile.hpp"
#include "support/CaseRunner.hpp"

#include <cmath>
#include <iostream>

using namespace sph;

TEST_CASE("colliding rings, coarse: contact, energy, momentum, symmetry", "[rings]")
{
    test::TempDir dir;
    const auto caseDir = test::copyTutorial("rings2D/collidingRings", dir.path());
    REQUIRE(test::runParticles(caseDir, {"-set", "ringA.spacing=2e-3", "-set", "ringB.spacing=2e-3"}) == 0);
    REQUIRE(test::runSolver(caseDir, {"-set", "endTime=0.013", "-set", "writeInterval=1e-3"}) == 0);

    // Interpenetration: the closest particles of different rings at every output.
    PvdSeries series(caseDir / "VTK" / "collidingRings.pvd");
    series.load();
    REQUIRE(series.entries().size() >= 13);
    double closest = 1.0;
    for (const auto& entry : series.entries())
    {
        const VtuData data = readVtu(caseDir / "VTK" / entry.file);
        const auto& body = data.pointData.at("bodyId").values;
        for (std::size_t a = 0; a < data.pointCount(); ++a)
        {
            for (std::size_t b = a + 1; b < data.pointCount(); ++b)
            {
                if (body[a] != body[b])
                {
                    const double dx = data.points[3 * a] - data.points[3 * b];
                    const double dy = data.points[3 * a + 1] - data.points[3 * b + 1];
                    closest = std::min(closest, std::hypot(dx, dy));
                }
            }
        }
    }
    std::cout << "rings: closest particles of different rings " << closest / 2e-3 << " spacings\n";
    CHECK(closest > 0.5 * 2e-3);

    const auto energy = test::readTable(caseDir / "postProcessing/energy/energy.dat");
    const auto total = energy.column("total");
    const auto contact = energy.column("contact");
    const auto momentumX = energy.column("momentum_x");
    const auto momentumY = energy.column("momentum_y");
    const auto kinetic = energy.column("kinetic");
    double drift = 0.0;
    double momentum = 0.0;
    for (std::size_t i = 0; i < total.size(); ++i)
    {
        drift = std::max(drift, std::abs(total[i] / total[0] - 1.0));
        momentum = std::max(momentum, std::hypot(momentumX[i], momentumY[i]));
    }
    // The momentum of one ring: m v = rho A v.
    const double scale = std::sqrt(2.0 * kinetic[0] * (kinetic[0] / (0.5 * 0.59 * 0.59)) / 2.0);
    std::cout << "rings: energy balance error " << drift << ", contact work " << contact.back()
              << " J, |momentum| " << momentum << " (one ring " << scale << ")\n";
    CHECK(contact.back() != 0.0); // the rings did touch
    CHECK(drift < 0.02);
    CHECK(momentum < 1e-10 * scale);

    const auto extent = test::readTable(caseDir / "postProcessing/extent/extent.dat");
    const auto a = extent.column("ringA_maxDisplacement");
    const auto b = extent.column("ringB_maxDisplacement");
    double peak = 0.0;
    double asymmetry = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        peak = std::max(peak, std::abs(a[i]));
        asymmetry = std::max(asymmetry, std::abs(a[i] - b[i]));
    }
    std::cout << "rings: largest y-displacement " << peak << " m, largest difference between "
              << "the rings " << asymmetry << " m\n";
    REQUIRE(peak > 1e-3);
    CHECK(asymmetry < 0.01 * peak);
}
