// The `surfaceProfile` function object (functionObjects/surfaceProfile): the free surface of a
// block at rest column by column (highest centre + half a spacing), its front and top, the
// largest vertical distance to a reference profile and the mean and rms over the columns,
// computed by hand, the profile tables, and
// clean errors for a missing or garbled reference file.
#include "solver/SolverCases.hpp"

#include <sys/stat.h>

using namespace sph;

namespace
{

// A 4 x 2 block (spacing 1 cm) of stiff material at rest; `reference` is written to ref.csv.
std::filesystem::path writeProfileCase(const std::filesystem::path& folder,
                                       const std::string& reference)
{
    const auto caseDir = test::writeWallCase(
        folder, 2, "block { type box; min (0 0); max (0.04 0.02); spacing 0.01; }",
        "block { material $stiff; }", "", 1e-4);
    std::ofstream(caseDir / "system" / "controlDict")
        << "endTime 1e-4;\ncourant 0.3;\nwriteInterval 1e-4;\nfunctions\n{\n"
        << "    surface { type surfaceProfile; writeInterval 1e-4; reference \"ref.csv\"; }\n}\n";
    std::ofstream(caseDir / "ref.csv") << reference;
    return caseDir;
}

} // namespace

TEST_CASE("surfaceProfile: front, top and the largest distance to a reference, by hand",
          "[surfaceProfile][functionObjects]")
{
    test::TempDir dir;
    // Columns centred at x = 5, 15, 25, 35 mm, each 0.02 m high; beyond x = 40 mm the floor.
    // At x = 0 the surface is the first column's, 0.02 (reference 0.03: distance 0.01); at
    // x = 0.04, halfway from the last centre (0.02) to the floor: 0.01 (reference 0.01: 0);
    // at 0.02: 0.02 (reference 0.015: 0.005).
    const auto caseDir =
        writeProfileCase(dir.path() / "block", "# a comment\nx,y\n0,0.03\n0.02 0.015\n0.04,0.01\n");
    REQUIRE(test::runParticles(caseDir) == 0);
    std::string output;
    REQUIRE(test::runProcess("sphSolid", {"-case", caseDir.string()}, &output) == 0);
    INFO(output);
    CHECK(test::summaryValue(caseDir, "functions/surface/front") == Approx(0.04).epsilon(1e-9));
    CHECK(test::summaryValue(caseDir, "functions/surface/top") == Approx(0.02).epsilon(1e-9));
    CHECK(test::summaryValue(caseDir, "functions/surface/largestDistance") ==
          Approx(0.01).epsilon(1e-6));
    CHECK(test::summaryValue(caseDir, "functions/surface/atX") == 0.0);
    // Over the four columns (the reference at 5, 15, 25, 35 mm: 0.02625, 0.01875, 0.01375,
    // 0.01125): height − reference = −0.00625, 0.00125, 0.00625, 0.00875.
    CHECK(test::summaryValue(caseDir, "functions/surface/meanDistance") ==
          Approx(0.0025).epsilon(1e-6));
    CHECK(test::summaryValue(caseDir, "functions/surface/rmsDistance") ==
          Approx(0.00625).epsilon(1e-6));
    CHECK(test::summaryValue(caseDir, "functions/surface/depositEnd") ==
          Approx(0.04).epsilon(1e-9));
    CHECK_THAT(output, Catch::Contains("surface: front 0.04 m, top 0.02 m, deposit end 0.04 m, "
                                       "largest distance to the reference 0.01 m at x = 0 m"));
    const auto profile =
        test::readTable(caseDir / "postProcessing" / "surface" / "surface_0.0001.dat");
    CHECK(profile.column("x") == std::vector<double>{0.005, 0.015, 0.025, 0.035});
    for (const double h : profile.column("height"))
    {
        CHECK(h == Approx(0.02).epsilon(1e-9));
    }
    CHECK(profile.column("reference").front() == Approx(0.02625).epsilon(1e-9)); // 0.03 - 0.015/4
}

TEST_CASE("surfaceProfile: a detached block moves the front, not the deposit's end",
          "[surfaceProfile][functionObjects]")
{
    test::TempDir dir;
    // The 4 x 2 block (columns 0-3) and a 2 x 2 one at x = 60-80 mm (columns 6, 7): columns
    // 4 and 5 are empty, so the deposit ends at 0.04 m and the front is 0.08 m.
    const auto caseDir =
        test::writeWallCase(dir.path() / "stray", 2,
                            "block { type box; min (0 0); max (0.04 0.02); spacing 0.01; }\n"
                            "stray { type box; min (0.06 0); max (0.08 0.02); spacing 0.01; }",
                            "block { material $stiff; }\nstray { material $stiff; }", "", 1e-4);
    std::ofstream(caseDir / "system" / "controlDict")
        << "endTime 1e-4;\ncourant 0.3;\nwriteInterval 1e-4;\nfunctions\n{\n"
        << "    surface { type surfaceProfile; writeInterval 1e-4; }\n}\n";
    REQUIRE(test::runParticles(caseDir) == 0);
    REQUIRE(test::runSolver(caseDir) == 0);
    CHECK(test::summaryValue(caseDir, "functions/surface/front") == Approx(0.08).epsilon(1e-9));
    CHECK(test::summaryValue(caseDir, "functions/surface/depositEnd") ==
          Approx(0.04).epsilon(1e-9));
    // Without a reference there is no distance to report (not a value read past the row).
    std::ifstream summary(caseDir / "postProcessing" / "summary.json");
    const std::string json((std::istreambuf_iterator<char>(summary)),
                           std::istreambuf_iterator<char>());
    CHECK(json.find("largestDistance") == std::string::npos);
    const auto profile =
        test::readTable(caseDir / "postProcessing" / "surface" / "surface_0.0001.dat");
    const std::vector<double> expected{0.02, 0.02, 0.02, 0.02, 0.0, 0.0, 0.02, 0.02};
    const auto height = profile.column("height");
    REQUIRE(height.size() == expected.size());
    for (std::size_t c = 0; c < expected.size(); ++c)
    {
        CHECK(height[c] == Approx(expected[c]).margin(1e-12));
    }
}

TEST_CASE("surfaceProfile: a missing or garbled reference is an input error at its key",
          "[surfaceProfile][functionObjects][errors]")
{
    test::TempDir dir;
    const auto garbled = writeProfileCase(dir.path() / "garbled", "x,y\n0,0.03\n0.02 high\n");
    REQUIRE(test::runParticles(garbled) == 0);
    std::string output;
    CHECK(test::runProcess("sphSolid", {"-case", garbled.string(), "-dryRun"}, &output) == 1);
    CHECK_THAT(output, Catch::Contains("system/controlDict:6:") &&
                           Catch::Contains("ref.csv:3: not an 'x y' pair of numbers"));
    const auto missing = writeProfileCase(dir.path() / "missing", "");
    std::filesystem::remove(missing / "ref.csv");
    REQUIRE(test::runParticles(missing) == 0);
    output.clear();
    CHECK(test::runProcess("sphSolid", {"-case", missing.string(), "-dryRun"}, &output) == 1);
    CHECK_THAT(output, Catch::Contains("system/controlDict:6:") &&
                           Catch::Contains("cannot read the reference profile") &&
                           Catch::Contains("ref.csv': no such file"));
    // Not a regular file: a device is read until memory runs out, a FIFO blocks for ever
    // (issue 31): both refused before they are opened.
    for (const std::string kind : {"device", "fifo"})
    {
        const auto special = writeProfileCase(dir.path() / kind, "");
        std::filesystem::remove(special / "ref.csv");
        if (kind == "device")
        {
            std::filesystem::create_symlink("/dev/zero", special / "ref.csv");
        }
        else
        {
            REQUIRE(mkfifo((special / "ref.csv").c_str(), 0600) == 0);
        }
        REQUIRE(test::runParticles(special) == 0);
        output.clear();
        CHECK(test::runProcess("sphSolid", {"-case", special.string(), "-dryRun"}, &output) == 1);
        CHECK_THAT(output, Catch::Contains("system/controlDict:6:") &&
                               Catch::Contains("ref.csv': it is not a regular file"));
    }
}

TEST_CASE("surfaceProfile in 3D: the slice's columns only, and 'slice' checked",
          "[surfaceProfile][functionObjects]")
{
    test::TempDir dir;
    // A 4 x 2 x 4 slab (spacing 1 cm, z in [0, 0.04]) and, outside the slice z in [0.015,
    // 0.025], a 2 x 2 x 2 post on it at x = 0-20 mm, z = 30-50 mm (top 0.04) and a 2 x 2 x 2
    // block at x = 60-80 mm, z = 0-10 mm: the slice's profile is the slab's alone (every
    // column 0.02 high, front 0.04), the spacing V0^(1/3).
    const auto caseDir = test::writeWallCase(
        dir.path() / "slab", 3,
        "slab { type box; min (0 0 0); max (0.04 0.02 0.04); spacing 0.01; }\n"
        "post { type box; min (0 0.02 0.03); max (0.02 0.04 0.05); spacing 0.01; }\n"
        "far  { type box; min (0.06 0 -0.01); max (0.08 0.02 0.01); spacing 0.01; }",
        "slab { material $stiff; }\npost { material $stiff; }\nfar { material $stiff; }", "", 1e-4);
    const auto writeControl = [&](const std::string& keys)
    {
        std::ofstream(caseDir / "system" / "controlDict")
            << "endTime 1e-4;\ncourant 0.3;\nwriteInterval 1e-4;\nfunctions\n{\n"
            << "    surface { type surfaceProfile; writeInterval 1e-4; " << keys << " }\n}\n";
    };
    writeControl("slice (0.015 0.025);");
    REQUIRE(test::runParticles(caseDir) == 0);
    std::string output;
    REQUIRE(test::runProcess("sphSolid", {"-case", caseDir.string()}, &output) == 0);
    INFO(output);
    CHECK(test::summaryValue(caseDir, "functions/surface/front") == Approx(0.04).epsilon(1e-9));
    CHECK(test::summaryValue(caseDir, "functions/surface/top") == Approx(0.02).epsilon(1e-9));
    CHECK(test::summaryValue(caseDir, "functions/surface/depositEnd") ==
          Approx(0.04).epsilon(1e-9));
    const auto profile =
        test::readTable(caseDir / "postProcessing" / "surface" / "surface_0.0001.dat");
    CHECK(profile.column("x") == std::vector<double>{0.005, 0.015, 0.025, 0.035});
    // The whole depth: the post and the far block count.
    writeControl("slice (-1 1);");
    REQUIRE(test::runProcess("sphSolid", {"-case", caseDir.string()}, &output) == 0);
    CHECK(test::summaryValue(caseDir, "functions/surface/front") == Approx(0.08).epsilon(1e-9));
    CHECK(test::summaryValue(caseDir, "functions/surface/top") == Approx(0.04).epsilon(1e-9));
    // Bad input: missing in 3D, not two increasing numbers.
    for (const auto& [keys, message] :
         {std::pair{std::string(""), std::string("'slice' is missing")},
          std::pair{std::string("slice (0.02 0.01);"), std::string("two numbers zMin < zMax")},
          std::pair{std::string("slice (0.02);"), std::string("two numbers zMin < zMax")}})
    {
        writeControl(keys);
        output.clear();
        CHECK(test::runProcess("sphSolid", {"-case", caseDir.string(), "-dryRun"}, &output) == 1);
        CHECK_THAT(output, Catch::Contains("system/controlDict:") && Catch::Contains(message) &&
                               Catch::Contains("slice"));
    }
}

TEST_CASE("surfaceProfile in 2D refuses 'slice'", "[surfaceProfile][functionObjects][errors]")
{
    test::TempDir dir;
    const auto caseDir = writeProfileCase(dir.path() / "flat", "0 0.02\n0.04 0.02\n");
    std::ofstream(caseDir / "system" / "controlDict")
        << "endTime 1e-4;\ncourant 0.3;\nwriteInterval 1e-4;\nfunctions\n{\n"
        << "    surface { type surfaceProfile; slice (0 1); }\n}\n";
    REQUIRE(test::runParticles(caseDir) == 0);
    std::string output;
    CHECK(test::runProcess("sphSolid", {"-case", caseDir.string(), "-dryRun"}, &output) == 1);
    CHECK_THAT(output, Catch::Contains("system/controlDict:6:") &&
                           Catch::Contains("which a 2D run does not have"));
}
