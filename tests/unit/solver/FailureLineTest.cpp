// The `failureLine` function object (functionObjects/failureLine): on a 4 x 3 block whose
// particles above a staircase are launched at 2 m/s and the others left at rest, the failure
// height of each column of initial X, the toe, the angle of the line and the unmoved area,
// against the values worked out by hand.
#include "solver/SolverCases.hpp"

using namespace sph;

TEST_CASE("failureLine: failure heights, toe, angle and unmoved area, by hand",
          "[failureLine][functionObjects]")
{
    test::TempDir dir;
    // Spacing 1 cm: columns centred at X = 5, 15, 25, 35 mm, rows at Y = 5, 15, 25 mm. Moved:
    // column 1's top particle, column 2's upper two, all of column 3. A soft material (c0 = 12
    // m/s): in the three steps of the run (1 ms) the particles at rest are hardly disturbed.
    const auto caseDir = test::writeWallCase(
        dir.path() / "staircase", 2, "block { type box; min (0 0); max (0.04 0.03); spacing 0.01; }",
        "block { material $stiff; }", "", 1e-4);
    std::ofstream(caseDir / "constant" / "bodies")
        << "block\n{\n    material { type linearElastic; E 1e5; nu 0.3; rho 1000; }\n"
        << "    initialVelocity\n    {\n"
        << "        one   { region { type box; min (0.01 0.02); max (0.02 0.03); } velocity (0 2); }\n"
        << "        two   { region { type box; min (0.02 0.01); max (0.03 0.03); } velocity (0 2); }\n"
        << "        three { region { type box; min (0.03 0); max (0.04 0.03); } velocity (0 2); }\n"
        << "    }\n}\n";
    std::ofstream(caseDir / "system" / "controlDict")
        << "endTime 1e-3;\ncourant 0.3;\nwriteInterval 1e-3;\nfunctions\n{\n"
        << "    failure { type failureLine; threshold 1e-3; writeInterval 1e-3; }\n}\n";
    REQUIRE(test::runParticles(caseDir) == 0);
    std::string output;
    const int status = test::runProcess("sphSolid", {"-case", caseDir.string()}, &output);
    INFO(output);
    REQUIRE(status == 0);
    // Failure heights 0.03 (nothing moved), 0.02, 0.01, 0 (the base moved): the toe is column
    // 3's left edge; the points strictly inside their columns, (0.015, 0.02) and (0.025, 0.01),
    // fall at 45°; six particles of 1 cm² stay.
    CHECK(test::summaryValue(caseDir, "functions/failure/toe") == Approx(0.03).epsilon(1e-9));
    CHECK(test::summaryValue(caseDir, "functions/failure/angle") == Approx(45.0).epsilon(1e-9));
    CHECK(test::summaryValue(caseDir, "functions/failure/unmovedArea") == Approx(6e-4).epsilon(1e-9));
    CHECK_THAT(output, Catch::Contains("failure: toe 0.03 m, angle 45 deg, unmoved area 0.0006 m^2"));
    const auto table = test::readTable(caseDir / "postProcessing" / "failure" / "failure_0.001.dat");
    CHECK(table.column("X") == std::vector<double>{0.005, 0.015, 0.025, 0.035});
    const std::vector<double> expected{0.03, 0.02, 0.01, 0.0};
    const auto height = table.column("failureHeight");
    REQUIRE(height.size() == expected.size());
    for (std::size_t c = 0; c < expected.size(); ++c)
    {
        CHECK(height[c] == Approx(expected[c]).margin(1e-12));
    }
}
