// One run per case folder (issue 31 item 11; core/CaseLock.hpp, core/Process.hpp): a second
// sphSolid in a case refuses and names the first (program, pid, host, start time), the lock of
// a killed run is taken over with a line saying so, processes mpirun started without -parallel
// refuse, and sphStudy's run under way ends with the study, even when the study is killed.
#include "core/CaseLock.hpp"
#include "solver/SolverCases.hpp"
#include "support/BackgroundProcess.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <climits>
#include <fstream>
#include <thread>

using namespace sph;

namespace
{

const std::string schemes = "kernel { type cubicSpline; }\nformulation { type totalLagrangian; }\n"
                            "stabilisation { type none; }";

std::string hostName()
{
    char name[HOST_NAME_MAX + 1] = {};
    REQUIRE(gethostname(name, sizeof name) == 0);
    return name;
}

// Waits (at most 60 s) until `ready` holds.
template <class Condition>
void waitUntil(const Condition& ready, const std::string& what)
{
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!ready())
    {
        if (std::chrono::steady_clock::now() > deadline)
        {
            FAIL("not within 60 s: " << what);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

// The sphSolid that `study` runs, once it runs and has written its first outputs (it stops
// gracefully from then on).
pid_t solverOf(const test::BackgroundProcess& study, const std::filesystem::path& run)
{
    waitUntil([&] { return std::filesystem::exists(run / "VTK" / "long_1.vtu"); },
              "the study's run writes");
    pid_t solver = 0;
    waitUntil(
        [&]
        {
            for (const pid_t child : test::childrenOf(study.pid()))
            {
                std::ifstream comm("/proc/" + std::to_string(child) + "/comm");
                std::string name;
                std::getline(comm, name);
                if (name == "sphSolid")
                {
                    solver = child;
                    return true;
                }
            }
            return false;
        },
        "sphStudy starts sphSolid");
    return solver;
}

} // namespace

TEST_CASE("a second run in a case refuses and names the first, a killed run's lock is taken over",
          "[lock]")
{
    test::TempDir dir;
    const auto caseDir = test::writeBlockCase(dir.path() / "block", schemes, 1e-3, 1e-4);
    REQUIRE(test::runParticles(caseDir) == 0);
    const auto lockFile = CaseLock::fileOf(caseDir);
    {
        // Far beyond the test: it runs until killed.
        test::BackgroundProcess first("sphSolid", {"-case", caseDir.string(), "-set", "endTime=100"},
                                      dir.path() / "first.log");
        waitUntil([&] { return std::filesystem::exists(caseDir / "VTK" / "block_1.vtu"); },
                  "the first run writes");
        std::string output;
        CHECK(test::runProcess("sphSolid", {"-case", caseDir.string()}, &output) == 1);
        INFO(output);
        CHECK_THAT(output, Catch::Contains("FATAL INPUT ERROR"));
        CHECK_THAT(output, Catch::Contains("is in use: sphSolid, pid " +
                                           std::to_string(first.pid()) + " on host " +
                                           hostName() + ", started 20"));
        CHECK_THAT(output, Catch::Contains("Wait until that run ends"));
        // A dry run writes nothing: it may read a case in use.
        CHECK(test::runProcess("sphSolid", {"-case", caseDir.string(), "-dryRun"}) == 0);
        // Nor may sphParticles write the particles of a case in use.
        output.clear();
        CHECK(test::runProcess("sphParticles", {"-case", caseDir.string()}, &output) == 1);
        CHECK_THAT(output, Catch::Contains("is in use: sphSolid, pid " +
                                           std::to_string(first.pid())));
        CHECK(test::runProcess("sphParticles", {"-case", caseDir.string(), "-dryRun"}) == 0);
        first.signal(SIGKILL); // no chance to release the lock's file
        first.wait();
    }
    CHECK_THAT(test::fileText(lockFile), Catch::Contains("sphSolid, pid"));
    std::string output;
    CHECK(test::runProcess("sphSolid", {"-case", caseDir.string()}, &output) == 0);
    INFO(output);
    CHECK_THAT(output, Catch::Contains("Lock        taken over the lock of sphSolid, pid"));
    CHECK_THAT(output, Catch::Contains("which no longer runs"));
    CHECK(test::fileText(lockFile).empty()); // released at the end
}

TEST_CASE("sphSolid started as several processes by mpirun without -parallel refuses", "[lock]")
{
    test::TempDir dir;
    const auto caseDir = test::writeBlockCase(dir.path() / "block", schemes, 1e-3, 1e-4);
    REQUIRE(test::runParticles(caseDir) == 0);
    // What mpirun -np 2 (Open MPI) sets in each process it starts.
    for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    {
        INFO(variable);
        REQUIRE(setenv(variable, "2", 1) == 0);
        std::string output;
        const int code = test::runProcess("sphSolid", {"-case", caseDir.string()}, &output);
        unsetenv(variable);
        INFO(output);
        CHECK(code == 1);
        CHECK_THAT(output, Catch::Contains("sphSolid is one of 2 processes mpirun started, "
                                           "without -parallel"));
        CHECK_THAT(output, Catch::Contains("mpirun -np 2 sphSolid -parallel"));
        CHECK(!std::filesystem::exists(caseDir / "VTK"));
    }
}

TEST_CASE("the run under way ends with sphStudy, killed or stopped, and one study runs at a time",
          "[lock][study]")
{
    test::TempDir dir;
    const auto caseDir = test::writeBlockCase(dir.path() / "block", schemes, 1e-3, 1e-4);
    std::ofstream(caseDir / "system" / "studyDict")
        << "axes { length { long { solver (\"endTime=100\"); } } }\nthreads 1;\n"
           "metrics { steps { type summary; value steps; } }\n";
    const auto run = caseDir / "postProcessing" / "study" / "runs" / "long";
    SECTION("killed: SIGKILL leaves no handler, the run gets SIGTERM from the system")
    {
        test::BackgroundProcess study("sphStudy", {"-case", caseDir.string()}, dir.path() / "log");
        const pid_t solver = solverOf(study, run);
        study.signal(SIGKILL);
        study.wait();
        waitUntil([&] { return !test::alive(solver); }, "sphSolid ends with sphStudy");
        // It stopped gracefully: its last level written, its summary says by what.
        std::ifstream in(run / "postProcessing" / "summary.json");
        REQUIRE(in);
        CHECK(nlohmann::json::parse(in).at("stoppedBy") == "SIGTERM");
    }
    SECTION("a second study in the same folder refuses: it would remove the first one's runs")
    {
        test::BackgroundProcess study("sphStudy", {"-case", caseDir.string()}, dir.path() / "log");
        const pid_t solver = solverOf(study, run);
        std::string output;
        CHECK(test::runProcess("sphStudy", {"-case", caseDir.string()}, &output) == 1);
        CHECK_THAT(output, Catch::Contains("is in use: sphStudy, pid " +
                                           std::to_string(study.pid())));
        CHECK(test::alive(solver)); // the first study's run goes on
        CHECK(std::filesystem::exists(run / "VTK" / "long_1.vtu"));
        study.signal(SIGTERM);
        study.wait();
    }
    SECTION("stopped: SIGTERM reaches the run, then ends the study, which records nothing")
    {
        test::BackgroundProcess study("sphStudy", {"-case", caseDir.string()}, dir.path() / "log");
        const pid_t solver = solverOf(study, run);
        study.signal(SIGTERM);
        const int status = study.wait();
        CHECK(WIFSIGNALED(status));
        CHECK(WTERMSIG(status) == SIGTERM);
        CHECK(!test::alive(solver));
        CHECK(!std::filesystem::exists(run / "study.json")); // resumed, it runs again
        std::ifstream in(run / "postProcessing" / "summary.json");
        REQUIRE(in);
        CHECK(nlohmann::json::parse(in).at("stoppedBy") == "SIGTERM");
    }
}
