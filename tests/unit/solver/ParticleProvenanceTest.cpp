// constant/particles.vtu records the system/particlesDict that made it, and sphSolid refuses
// particles made from another one (issue 32 item 1): editing particlesDict and running sphSolid
// without sphParticles ran the old particles without a word.
#include "solver/ParticleProvenance.hpp"
#include "core/InputError.hpp"
#include "io/VtuFile.hpp"
#include "solver/ParticleFile.hpp"
#include "support/CaseRunner.hpp"

#include <fstream>

using namespace sph;

namespace
{

// The Dyka bar with its particles made by sphParticles (with `sets`).
std::filesystem::path barWithParticles(const test::TempDir& dir,
                                       const std::vector<std::string>& sets = {})
{
    const auto caseDir = test::copyTutorial("bar1D/dykaBar", dir.path());
    std::vector<std::string> args;
    for (const auto& set : sets)
    {
        args.push_back("-set");
        args.push_back(set);
    }
    REQUIRE(test::runParticles(caseDir, args) == 0);
    return caseDir;
}

InitialParticles particlesOf(const std::filesystem::path& caseDir)
{
    return readParticleFile(particleFilePath(caseDir));
}

// The stale-particles error of the case, as the user sees it.
std::string staleError(const std::filesystem::path& caseDir)
{
    try
    {
        checkParticlesDict(particlesOf(caseDir), caseDir);
    }
    catch (const InputError& error)
    {
        return error.what();
    }
    FAIL("the particles were not found stale");
    return {};
}

} // namespace

TEST_CASE(
    "particle record: sphParticles records its particlesDict, and sphSolid accepts it unchanged",
    "[provenance]")
{
    test::TempDir dir;
    const auto caseDir = barWithParticles(dir);
    const InitialParticles particles = particlesOf(caseDir);
    CHECK(particles.particlesDictLines ==
          std::vector<std::string>{"bar.type line", "bar.start 0", "bar.end 0.1333", "bar.n 40"});
    CHECK(particles.particlesDictSets.empty());
    CHECK(checkParticlesDict(particles, caseDir) == "made from system/particlesDict as it is");
    // A comment or the layout is no change.
    test::setEntry(caseDir / "system" / "particlesDict", "// note", "x");
    CHECK_NOTHROW(checkParticlesDict(particles, caseDir));
}

TEST_CASE(
    "particle record: an edited particlesDict makes the particles stale: the entry and the fix",
    "[provenance]")
{
    test::TempDir dir;
    const auto caseDir = barWithParticles(dir);
    test::setEntry(caseDir / "system" / "particlesDict", "n", "80");
    const std::string text = staleError(caseDir);
    CHECK_THAT(text, Catch::Contains("system/particlesDict:8:5: constant/particles.vtu is stale: "
                                     "'bar.n' is 80 but was 40"));
    CHECK_THAT(text, Catch::Contains("Run sphParticles"));
    // sphSolid stops with it (exit 1) before running, also in a dry run.
    CHECK_THROWS_AS(test::runSolver(caseDir, {"-dryRun"}), InputError);
    std::string output;
    CHECK(test::runProcess("sphSolid", {"-case", caseDir.string()}, &output) == 1);
    CHECK_THAT(output, Catch::Contains("sphSolid FATAL INPUT ERROR"));
    CHECK_THAT(output, Catch::Contains("'bar.n' is 80 but was 40"));
    CHECK_FALSE(std::filesystem::exists(caseDir / "VTK"));
    // sphParticles again: current.
    REQUIRE(test::runParticles(caseDir) == 0);
    CHECK(test::runSolver(caseDir, {"-dryRun"}) == 0);
}

TEST_CASE("particle record: a new or removed entry is stale too", "[provenance]")
{
    test::TempDir dir;
    const auto caseDir = barWithParticles(dir);
    SECTION("a new body")
    {
        std::ofstream(caseDir / "system" / "particlesDict", std::ios::app)
            << "\nbar2 { type line; start 1; end 1.1333; n 40; }\n";
        CHECK_THAT(staleError(caseDir), Catch::Contains("'bar2.type' is new"));
    }
    SECTION("a removed key")
    {
        std::ofstream(caseDir / "system" / "particlesDict")
            << "bar { type line; start 0; end 0.1333; }\n";
        CHECK_THAT(staleError(caseDir),
                   Catch::Contains("system/particlesDict: constant/particles.vtu is stale: "
                                   "'bar.n' (40) is gone"));
    }
}

TEST_CASE("particle record: particles made with a -set are current with the same -set applied",
          "[provenance]")
{
    // As sphStudy does for its particle variants, and `sphParticles -set bar.n=160 && sphSolid`.
    test::TempDir dir;
    const auto caseDir = barWithParticles(dir, {"bar.n=20"});
    const InitialParticles particles = particlesOf(caseDir);
    CHECK(particles.size() == 20);
    CHECK(particles.particlesDictSets == std::vector<std::string>{"bar.n=20"});
    CHECK(checkParticlesDict(particles, caseDir) ==
          "made from system/particlesDict as it is, by sphParticles -set bar.n=20");
    CHECK(test::runSolver(caseDir, {"-dryRun"}) == 0);
    // An edit elsewhere in the file is still seen.
    test::setEntry(caseDir / "system" / "particlesDict", "end", "0.2");
    const std::string text = staleError(caseDir);
    CHECK_THAT(text, Catch::Contains("'bar.end' is 0.2 but was 0.1333"));
    CHECK_THAT(text, Catch::Contains("They were made by sphParticles -set bar.n=20."));
}

TEST_CASE("particle record: particles without a record still run, with a note", "[provenance]")
{
    // Files of older versions and other tools: the tutorials shipped such files.
    test::TempDir dir;
    const auto caseDir = barWithParticles(dir);
    VtuData data = readVtu(particleFilePath(caseDir));
    data.stringFields.erase("particlesDict");
    writeVtu(particleFilePath(caseDir), data);
    test::setEntry(caseDir / "system" / "particlesDict", "n", "80");
    CHECK_THAT(checkParticlesDict(particlesOf(caseDir), caseDir),
               Catch::Contains("does not record its system/particlesDict"));
    CHECK(test::runSolver(caseDir, {"-dryRun"}) == 0);
}
