// Particle files are validated where they are read (issue 12 item 3): a damaged
// constant/particles.vtu, restart output or imported .vtu is an input error (exit code 1) naming
// the file, the array and the particle, never a crash or an "internal error". The files are
// damaged through the project's own reader and writer (io/VtuFile), so every value VTK can hold
// (NaN, a fractional id, a wrong component count) can be tried.
#include "io/PvdSeries.hpp"
#include "io/VtuFile.hpp"
#include "support/CaseRunner.hpp"

#include <fstream>
#include <functional>
#include <iterator>
#include <limits>

using namespace sph;

namespace
{

const double notANumber = std::numeric_limits<double>::quiet_NaN();

// A 1D bar of 5 particles (spacing 1 cm) with its particles written by sphParticles.
std::filesystem::path writeBar(const std::filesystem::path& folder)
{
    std::filesystem::create_directories(folder / "system");
    std::filesystem::create_directories(folder / "constant");
    std::ofstream(folder / "system" / "controlDict")
        << "endTime 1e-4;\ncourant 0.3;\nwriteInterval 1e-4;\n";
    std::ofstream(folder / "system" / "sphSchemes")
        << "dimension 1;\nkernel { type cubicSpline; hOverDx 1.5; }\n"
        << "formulation { type totalLagrangian; }\nstabilisation { type none; }\n";
    std::ofstream(folder / "system" / "particlesDict")
        << "bar { type line; start 0; end 0.04; n 5; }\n";
    std::ofstream(folder / "constant" / "bodies")
        << "bar { material { type linearElastic; E 1e7; rho 1000; } "
        << "constraints { end { type fixed; region { type nearest; point (0); } } } }\n";
    REQUIRE(test::runParticles(folder) == 0);
    return folder;
}

// Reads `file`, lets `damage` change it and writes it back.
void damage(const std::filesystem::path& file, const std::function<void(VtuData&)>& change)
{
    VtuData data = readVtu(file);
    change(data);
    writeVtu(file, data);
}

// Runs `app` on the case; requires exit code 1 and every fragment in the output.
std::string requireInputFailure(const std::string& app, const std::filesystem::path& caseDir,
                                const std::vector<std::string>& args,
                                const std::vector<std::string>& fragments)
{
    std::vector<std::string> all{"-case", caseDir.string()};
    all.insert(all.end(), args.begin(), args.end());
    std::string output;
    const int code = test::runProcess(app, all, &output);
    INFO(output);
    CHECK(code == 1);
    CHECK_THAT(output, Catch::Contains("FATAL INPUT ERROR"));
    for (const auto& fragment : fragments)
    {
        CHECK_THAT(output, Catch::Contains(fragment));
    }
    return output;
}

// A damaged constant/particles.vtu under sphSolid -dryRun.
void requireParticleFileError(const std::function<void(VtuData&)>& change,
                              const std::vector<std::string>& fragments)
{
    test::TempDir dir;
    const auto caseDir = writeBar(dir.path() / "bar");
    const auto file = caseDir / "constant" / "particles.vtu";
    damage(file, change);
    auto all = fragments;
    all.push_back(file.string() + ": ");
    all.push_back(
        "The file is damaged or was not written by sphParticles; run sphParticles again.");
    requireInputFailure("sphSolid", caseDir, {"-dryRun"}, all);
}

std::vector<double>& values(VtuData& data, const std::string& point)
{
    return data.pointData.at(point).values;
}

} // namespace

TEST_CASE("particle file: a body id out of range names the particle and the valid ids",
          "[particleFile]")
{
    requireParticleFileError([](VtuData& d) { values(d, "bodyId")[4] = 7; },
                             {"particle 4 (at 0.04 0 0): its array 'bodyId' is 7; it must be a "
                              "whole number from 0 to 0"});
    requireParticleFileError([](VtuData& d) { values(d, "bodyId")[1] = -1; },
                             {"particle 1 (at 0.01 0 0): its array 'bodyId' is -1"});
    requireParticleFileError(
        [](VtuData& d)
        {
            auto& bodyId = d.pointData.at("bodyId");
            bodyId.integer = false; // written as Float64: an Int32 cannot hold 0.5
            bodyId.values[2] = 0.5;
        },
        {"particle 2 (at 0.02 0 0): its array 'bodyId' is 0.5"});
}

TEST_CASE("particle file: the spacing must be finite and positive", "[particleFile]")
{
    requireParticleFileError([](VtuData& d) { d.fieldData.at("spacing").values[0] = 0; },
                             {"its field data 'spacing' is 0; it must be > 0"});
    requireParticleFileError([](VtuData& d) { d.fieldData.at("spacing").values[0] = -0.01; },
                             {"its field data 'spacing' is -0.01; it must be > 0"});
    requireParticleFileError([](VtuData& d) { d.fieldData.at("spacing").values[0] = notANumber; },
                             {"its field data 'spacing' is nan; it must be finite"});
    requireParticleFileError([](VtuData& d) { d.fieldData.at("spacing").values.clear(); },
                             {"its field data 'spacing' holds 0 values, not 1"});
    requireParticleFileError(
        [](VtuData& d) { d.fieldData.at("dimension").values[0] = 7; },
        {"its field data 'dimension' is 7; it must be a whole number from 1 to 3"});
}

TEST_CASE("particle file: positions must be finite and within reach of the neighbour grid",
          "[particleFile]")
{
    requireParticleFileError(
        [](VtuData& d) { d.points[3 * 2] = notANumber; },
        {"particle 2 has the position (nan 0 0); every coordinate must be finite"});
    requireParticleFileError(
        [](VtuData& d) { d.points[3 * 3] = 1e308; },
        {"particle 3 has x = 1e+308, but the particles must lie within 1e+06 spacings"});
}

TEST_CASE("particle file: volumes must be finite and positive, one per particle", "[particleFile]")
{
    requireParticleFileError([](VtuData& d) { values(d, "volume")[3] = 0; },
                             {"particle 3 (at 0.03 0 0): its array 'volume' is 0; it must be > 0"});
    requireParticleFileError([](VtuData& d) { values(d, "volume")[0] = -1; },
                             {"particle 0 (at 0 0 0): its array 'volume' is -1; it must be > 0"});
    requireParticleFileError(
        [](VtuData& d) { values(d, "volume")[1] = notANumber; },
        {"particle 1 (at 0.01 0 0): its array 'volume' is nan; it must be finite"});
    requireParticleFileError(
        [](VtuData& d)
        {
            auto& volume = d.pointData.at("volume");
            volume.components = 5;
            volume.values.resize(25, 1e-2);
        },
        {"its array 'volume' has 5 components, not 1"});
    requireParticleFileError([](VtuData& d) { d.pointData.erase("bodyId"); },
                             {"it has no array 'bodyId'"});
}

TEST_CASE("restart: a damaged output is an input error naming the file, array and particle",
          "[particleFile][restart]")
{
    test::TempDir dir;
    const auto caseDir = writeBar(dir.path() / "bar");
    REQUIRE(test::runSolver(caseDir) == 0);
    PvdSeries series(caseDir / "VTK" / "bar.pvd");
    series.load();
    REQUIRE(!series.entries().empty());
    const auto file = caseDir / "VTK" / series.entries().back().file;
    const VtuData good = readVtu(file);
    const auto restartWith =
        [&](const std::function<void(VtuData&)>& change, const std::string& fragment)
    {
        writeVtu(file, good);
        damage(file, change);
        requireInputFailure("sphSolid", caseDir,
                            {"-set", "controlDict.startFrom=latestTime", "-set", "endTime=2e-4"},
                            {"cannot restart from '" + file.string() + "': " + fragment,
                             "start afresh with startFrom startTime"});
    };
    restartWith(
        [](VtuData& d) { values(d, "restart:initialVolume")[2] = notANumber; },
        "particle 2 (at 0.02 0 0): its array 'restart:initialVolume' is nan; it must be finite");
    restartWith(
        [](VtuData& d)
        { values(d, "restart:velocityHalfStep")[4] = -std::numeric_limits<double>::infinity(); },
        "particle 4 (at 0.04 0 0): its array 'restart:velocityHalfStep' is -inf; it must be "
        "finite");
    restartWith(
        [](VtuData& d)
        {
            d.pointData.at("fixed").integer = false; // as Float64, to hold 0.5
            values(d, "fixed")[0] = 0.5;
        },
        "particle 0 (at 0 0 0): its array 'fixed' is 0.5; it must be a whole number");
    restartWith([](VtuData& d) { d.points[3] = notANumber; },
                "particle 1 has the position (nan 0 0)");
    restartWith([](VtuData& d) { d.fieldData.at("restart:step").values[0] = 1e300; },
                "its field data 'restart:step' is 1e+300; it must be a whole number");
    restartWith([](VtuData& d) { d.fieldData.at("TimeValue").values[0] = notANumber; },
                "its field data 'TimeValue' is nan; it must be finite");
}

TEST_CASE("vtu import: a point set with NaN or a non-positive volume is an input error",
          "[particleFile][generators]")
{
    test::TempDir dir;
    const auto caseDir = writeBar(dir.path() / "bar");
    const auto imported = caseDir / "constant" / "points.vtu";
    std::filesystem::copy_file(caseDir / "constant" / "particles.vtu", imported);
    std::ofstream(caseDir / "system" / "particlesDict")
        << "bar { type vtu; file \"constant/points.vtu\"; spacing 0.01; volumeArray volume; }\n";
    REQUIRE(test::runParticles(caseDir) == 0); // the undamaged file imports

    const VtuData good = readVtu(imported);
    const auto importWith =
        [&](const std::function<void(VtuData&)>& change, const std::vector<std::string>& fragments)
    {
        writeVtu(imported, good);
        damage(imported, change);
        requireInputFailure("sphParticles", caseDir, {}, fragments);
    };
    const std::string name = imported.string() + ": ";
    const std::string hint = "every coordinate and volume must be finite, every volume > 0";
    importWith([](VtuData& d) { d.points[3 * 4] = notANumber; },
               {name + "particle 4 has the position (nan 0 0)", hint});
    importWith(
        [](VtuData& d) { values(d, "volume")[2] = -1e-2; },
        {name + "particle 2 (at 0.02 0 0): its array 'volume' is -0.01; it must be > 0", hint});
    // Far out but finite: the bodies are checked together, before sphParticles writes them.
    importWith([](VtuData& d) { d.points[3 * 4] = 1e308; },
               {"system/particlesDict: particle 4 has x = 1e+308", "Check the bodies' positions"});
}

// A negative point count in the XML header reached VTK's reader unchecked and crashed it
// (issue 31): sphSolid -dryRun and a restart from such an output now stop with the file named.
TEST_CASE("particle file: a negative NumberOfPoints is an input error, not a crash",
          "[particleFile]")
{
    test::TempDir dir;
    const auto caseDir = writeBar(dir.path() / "bar");
    const auto file = caseDir / "constant" / "particles.vtu";
    std::string text;
    {
        std::ifstream in(file, std::ios::binary);
        text.assign(std::istreambuf_iterator<char>(in), {});
    }
    const auto at = text.find("NumberOfPoints=\"");
    REQUIRE(at != std::string::npos);
    const auto end = text.find('"', at + 16);
    text.replace(at, end - at + 1, "NumberOfPoints=\"-5\"");
    std::ofstream(file, std::ios::binary) << text;
    requireInputFailure("sphSolid", caseDir, {"-dryRun"},
                        {"particles.vtu': its NumberOfPoints is \"-5\", not a whole number >= 0"});
}
