// Plugins: a library named in a case's `libs` is loaded at run time and its models are
// selectable by name; a missing library is a fatal error with dlerror and a checklist.
#include "core/InputError.hpp"
#include "solver/Applications.hpp"
#include "support/CaseRunner.hpp"

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
    // -listTypes shows it once the case's libraries are loaded.
    std::ostringstream listing;
    listTypes(listing, "material");
    CHECK_THAT(listing.str(), Catch::Contains("pluginLinear"));
    CHECK_THAT(listing.str(), Catch::Contains("Test plugin"));
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
