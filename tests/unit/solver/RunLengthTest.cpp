// Values that would make a run take for ever, or write more than once per step, are input
// errors at the entry that caused them (issue 12, item 6: these used to hang with no output).
#include "core/InputError.hpp"
#include "support/CaseRunner.hpp"

using namespace sph;

namespace
{

// Runs the Dyka bar with `sets` and requires an InputError in `file` whose message contains
// `fragment`.
void requireRunError(const std::vector<std::string>& sets, const std::string& file,
                     const std::string& fragment)
{
    test::TempDir dir;
    const auto caseDir = test::copyTutorial("bar1D/dykaBar", dir.path());
    REQUIRE(test::runParticles(caseDir) == 0);
    std::vector<std::string> args;
    for (const auto& set : sets)
    {
        args.push_back("-set");
        args.push_back(set);
    }
    INFO(sets.front());
    try
    {
        test::runSolver(caseDir, args);
        FAIL("no error");
    }
    catch (const InputError& error)
    {
        CHECK(error.where().fileName() == file);
        CHECK_THAT(error.message(), Catch::Contains(fragment));
    }
}

} // namespace

TEST_CASE("an output interval below the time step is an input error, not a hang", "[schedule]")
{
    requireRunError({"writeInterval=1e-300"}, "command line",
                    "writeInterval 1e-300 s is shorter than the time step");
    requireRunError({"functions.energy.writeInterval=1e-300"}, "command line",
                    "writeInterval 1e-300 s is shorter than the time step");
}

TEST_CASE("a material whose own time step is longer than the run is an error at the material",
          "[schedule]")
{
    // Not at the output interval, which its enormous step would be far below (issue 31 item 9:
    // E 1e-300 was reported against writeInterval, at step 0 only).
    requireRunError({"bodies.bar.material.rho=1e300"}, "constant/bodies",
                    "body 'bar': its material's wave speed c = 1.73205e-148 m/s makes a time "
                    "step courant h / c = 2.96003e+143 s, longer than the whole run");
    requireRunError({"bodies.bar.material.E=1e-300"}, "constant/bodies",
                    "longer than the whole run (endTime 0.005 s)");
}

TEST_CASE("a run of more than 1e12 steps is an input error at endTime", "[schedule]")
{
    requireRunError({"endTime=1e300", "writeInterval=1e299"}, "command line",
                    "the run to endTime 1e+300 s would take");
}
