// Plugins: a library named in a case's `libs` is loaded at run time and its models are
// selectable by name; a missing library is a fatal error with dlerror and a checklist.
#include "core/InputError.hpp"
#include "core/ModelListing.hpp"
#include "solver/CaseSettings.hpp"
#include "io/PvdSeries.hpp"
#include "io/VtuFile.hpp"
#include "solver/SolverCases.hpp"

#include <fstream>
#include <sstream>

using namespace sph;

TEST_CASE("a case selects a model from its own plugin library", "[plugin]")
{
    test::TempDir dir;
    const auto caseDir = test::copyTutorial("bar1D/dykaBar", dir.path());
    test::setEntry(caseDir / "system" / "controlDict", "libs", "(\"" SPH_TEST_PLUGIN "\")");
    test::setEntry(caseDir / "system" / "controlDict", "endTime", "2e-4");
    std::ofstream(caseDir / "constant" / "bodies")
        << "bar { material { type pluginLinear; E 3e4; rho 1; }\n"
           "      constraints { end { type fixed; region { type nearest; point (0); } } }\n"
           "      velocity (1); }\n";
    REQUIRE(test::runParticles(caseDir) == 0);
    CHECK(test::runSolver(caseDir, {"-dryRun"}) == 0);
    CHECK(test::runSolver(caseDir) == 0);
    // Its run-header summary comes from the registry: name, keys as written, wave speed.
    std::string output;
    CHECK(test::runProcess("sphSolid", {"-case", caseDir.string(), "-dryRun"}, &output) == 0);
    CHECK_THAT(output, Catch::Contains("pluginLinear(rho=1, E=3e4, c=173.205 m/s)"));
    // -listTypes shows it once the case's libraries are loaded.
    std::ostringstream listing;
    listTypes(listing, "material");
    CHECK_THAT(listing.str(), Catch::Contains("pluginLinear"));
    CHECK_THAT(listing.str(), Catch::Contains("Test plugin"));
}

TEST_CASE("lists of valid types come from the registry: a plugin's models appear",
          "[plugin][schema]")
{
    test::TempDir dir;
    const auto caseDir = test::copyTutorial("bar1D/dykaBar", dir.path());
    test::setEntry(caseDir / "system" / "controlDict", "libs", "(\"" SPH_TEST_PLUGIN "\")");
    std::ofstream(caseDir / "constant" / "bodies") << "bar { velocity (1); }\n";
    REQUIRE(test::runParticles(caseDir) == 0);
    try
    {
        test::runSolver(caseDir, {"-dryRun"});
        FAIL("no error");
    }
    catch (const InputError& error)
    {
        CHECK_THAT(error.message(), Catch::Contains("missing required key 'material' in 'bar'"));
        CHECK_THAT(std::string(error.what()),
                   Catch::Contains("{ type hencky | j2Plasticity | linearElastic | neoHookean | pluginLinear | "
                                   "stVenantKirchhoff; rho ...; ... }"));
    }
    // The case dictionaries' documentation lists the plugin's function object as well.
    std::string functions;
    for (const std::string& line : ControlSettings::schema().describe())
    {
        functions += line.rfind("functions", 0) == 0 ? line : "";
    }
    CHECK_THAT(functions, Catch::Contains("pluginPeakSpeed"));
}

TEST_CASE("a missing plugin library is fatal with dlerror and a checklist", "[plugin]")
{
    test::TempDir dir;
    const auto caseDir = test::copyTutorial("bar1D/dykaBar", dir.path());
    test::setEntry(caseDir / "system" / "controlDict", "libs", "(\"libNoSuchModels.so\")");
    try
    {
        test::runSolver(caseDir, {"-dryRun"});
        FAIL("no error");
    }
    catch (const InputError& error)
    {
        CHECK(error.where().fileName() == "system/controlDict");
        CHECK_THAT(error.message(), Catch::Contains("cannot load library 'libNoSuchModels.so'"));
        const std::string text = error.what();
        CHECK_THAT(text, Catch::Contains("dlerror: "));
        CHECK_THAT(text, Catch::Contains("Checklist:"));
        CHECK_THAT(text, Catch::Contains("ldd"));
    }
}

namespace
{

// The Dyka bar with the plugin's history field: the largest speed of each particle.
std::filesystem::path peakSpeedCase(const std::filesystem::path& into)
{
    const auto caseDir = test::copyTutorial("bar1D/dykaBar", into);
    std::ofstream(caseDir / "system" / "controlDict")
        << "libs (\"" SPH_TEST_PLUGIN "\");\nendTime 1.5e-3;\ncourant 0.01;\n"
           "writeInterval 2e-4;\nfunctions { peak { type pluginPeakSpeed; } }\n";
    REQUIRE(test::runParticles(caseDir) == 0);
    return caseDir;
}

VtuData lastOutput(const std::filesystem::path& caseDir)
{
    PvdSeries series(caseDir / "VTK" / "dykaBar.pvd");
    series.load();
    REQUIRE(!series.entries().empty());
    return readVtu(caseDir / "VTK" / series.entries().back().file);
}

} // namespace

TEST_CASE("a plugin's own per-particle field is written, restarted and listed", "[plugin][fields]")
{
    test::TempDir one;
    test::TempDir two;
    const auto whole = peakSpeedCase(one.path());
    const auto split = peakSpeedCase(two.path());
    REQUIRE(test::runSolver(whole) == 0);
    REQUIRE(test::runSolver(split, {"-set", "endTime=7e-4"}) == 0);
    REQUIRE(test::runSolver(split, {"-set", "controlDict.startFrom=latestTime"}) == 0);

    const VtuData data = lastOutput(whole);
    // Written under its physical name, as a display field, in double precision.
    REQUIRE(data.pointData.count("peakSpeed"));
    const auto& peak = data.pointData.at("peakSpeed").values;
    const auto& velocity = data.pointData.at("velocity").values;
    REQUIRE(peak.size() == 40);
    CHECK(peak[39] >= 5.0); // the loaded end started at 5 m/s
    // It is history: somewhere the peak is well above the speed now.
    bool remembers = false;
    for (std::size_t a = 0; a < 40; ++a)
    {
        CHECK(peak[a] >= std::abs(velocity[3 * a]));
        remembers = remembers || peak[a] > std::abs(velocity[3 * a]) + 1.0;
    }
    CHECK(remembers);
    // A restart continues it bit for bit (every array and number of the last output).
    test::requireIdenticalState(data, lastOutput(split));

    std::ostringstream listing;
    listTypes(listing, "functionObject");
    CHECK_THAT(listing.str(), Catch::Contains("pluginPeakSpeed"));
    CHECK_THAT(listing.str(),
               Catch::Contains("peakSpeed  scalar, restart + display: largest |v| the particle"));
}
