// A graceful stop (issue 32, item 3; solver/StopRequest.hpp): SIGTERM or SIGINT finish the step,
// write a restartable level and postProcessing/summary.json ("stopped", by which signal) and
// exit with code 5; a second signal ends the process at once; `stopAt writeNow;` written into
// controlDict while running stops it alike (an invalid edit is reported and ignored); `startFrom
// startTime; startTime T;` continues from the output written at T.
#include "core/Application.hpp"
#include "io/PvdSeries.hpp"
#include "io/VtuFile.hpp"
#include "solver/SolverCases.hpp"
#include "solver/StopRequest.hpp"

#include "support/BackgroundProcess.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

using namespace sph;

namespace
{

nlohmann::json summaryOf(const std::filesystem::path& caseDir)
{
    std::ifstream in(caseDir / "postProcessing" / "summary.json");
    REQUIRE(in);
    return nlohmann::json::parse(in);
}

// A run stopped and continued ends as the uninterrupted one: the last state bit for bit, the
// tables and the .pvd byte for byte (the same outputs at the same times: the stopped level's
// file is overwritten by the next output, which has its number).
void requireSameRun(const std::filesystem::path& whole, const std::filesystem::path& split)
{
    test::requireIdenticalState(test::lastOutput(whole), test::lastOutput(split));
    for (const std::string table : {"freeEnd", "energy", "tipError"})
    {
        INFO(table);
        CHECK(test::fileText(whole / "postProcessing" / table / (table + ".dat")) ==
              test::fileText(split / "postProcessing" / table / (table + ".dat")));
    }
    CHECK(test::fileText(whole / "VTK" / "dykaBar.pvd") == test::fileText(split / "VTK" / "dykaBar.pvd"));
}

// sphSolid running in the background on a case, its output in `log`; killed if the test
// leaves it running.
class BackgroundSolver : public test::BackgroundProcess
{
public:
    BackgroundSolver(const std::filesystem::path& caseDir, const std::vector<std::string>& args,
                     const std::filesystem::path& log)
        : BackgroundProcess("sphSolid", withCase(caseDir, args), log), caseDir_(caseDir)
    {
    }

    // Waits until the series holds `count` outputs (at most 60 s).
    void waitForOutputs(std::size_t count) const
    {
        PvdSeries series(caseDir_ / "VTK" / (caseDir_.filename().string() + ".pvd"));
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        while (std::chrono::steady_clock::now() < deadline)
        {
            series.load();
            if (series.entries().size() >= count)
            {
                return;
            }
            REQUIRE(running());
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        FAIL("no " << count << " outputs after 60 s");
    }

private:
    static std::vector<std::string> withCase(const std::filesystem::path& caseDir,
                                             const std::vector<std::string>& args)
    {
        std::vector<std::string> all{"-case", caseDir.string()};
        all.insert(all.end(), args.begin(), args.end());
        return all;
    }

    std::filesystem::path caseDir_;
};

// The Dyka bar at 320 particles, an output every 1e-4 s: a few seconds to endTime 1.5e-3.
std::filesystem::path barCase(const std::filesystem::path& folder)
{
    const auto caseDir = test::copyTutorial("bar1D/dykaBar", folder);
    test::setEntry(caseDir / "system" / "controlDict", "endTime", "1.5e-3");
    REQUIRE(test::runParticles(caseDir, {"-set", "bar.n=320"}) == 0);
    return caseDir;
}

} // namespace

TEST_CASE("SIGTERM stops a run gracefully: a restartable level, the summary, exit 5 and the same result",
          "[stop][restart]")
{
    test::TempDir one;
    test::TempDir two;
    const auto whole = barCase(one.path());
    const auto split = barCase(two.path());
    REQUIRE(test::runSolver(whole) == 0);
    CHECK(summaryOf(whole).at("status") == "finished");
    CHECK(summaryOf(whole).at("stoppedBy") == "");

    const auto log = two.path() / "log.stopped";
    {
        BackgroundSolver solver(split, {}, log);
        solver.waitForOutputs(2);
        solver.signal(SIGTERM);
        const int status = solver.wait();
        INFO(test::fileText(log));
        REQUIRE(WIFEXITED(status));
        REQUIRE(WEXITSTATUS(status) == stoppedExitCode);
    }
    const std::string text = test::fileText(log);
    INFO(text);
    CHECK(text.find("Stopping    SIGTERM: writing step") != std::string::npos);
    CHECK(text.find("Stopped     by SIGTERM") != std::string::npos);
    const auto summary = summaryOf(split);
    CHECK(summary.at("status") == "stopped");
    CHECK(summary.at("stoppedBy") == "SIGTERM");
    CHECK(summary.at("failure") == "");
    // The level it stopped at is the last of the series, before endTime, and restartable.
    const VtuData stopped = test::lastOutput(split);
    const double stopTime = stopped.fieldData.at("TimeValue").values.at(0);
    CHECK(stopTime == summary.at("time").get<double>());
    CHECK(stopTime < 1.5e-3);
    CHECK(stopped.fieldData.at("restart:restartable").values.at(0) == 1.0);

    // Continued, it ends where the uninterrupted run does, bit for bit.
    REQUIRE(test::runSolver(split, {"-set", "controlDict.startFrom=latestTime"}) == 0);
    CHECK(summaryOf(split).at("status") == "finished");
    requireSameRun(whole, split);
}

TEST_CASE("SIGINT stops a run gracefully too and a second signal ends the process at once",
          "[stop]")
{
    // The handler itself, in a child process: the first signal is recorded and the process
    // goes on; the second one terminates it by that signal (the default action).
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0)
    {
        const StopSignals signals;
        raise(SIGINT);
        if (StopSignals::caught() != SIGINT)
        {
            _exit(10);
        }
        raise(SIGTERM);
        _exit(11); // not reached: SIGTERM ends the process
    }
    int status = 0;
    waitpid(child, &status, 0);
    REQUIRE(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == SIGTERM);

    // sphSolid stopped by SIGINT (Ctrl-C) says so.
    test::TempDir dir;
    const auto caseDir = barCase(dir.path());
    BackgroundSolver solver(caseDir, {}, dir.path() / "log");
    solver.waitForOutputs(2);
    solver.signal(SIGINT);
    const int ended = solver.wait();
    REQUIRE(WIFEXITED(ended));
    CHECK(WEXITSTATUS(ended) == stoppedExitCode);
    CHECK(summaryOf(caseDir).at("stoppedBy") == "SIGINT");
}

TEST_CASE("stopAt writeNow written into controlDict while running stops the run and an invalid "
          "edit is reported while the run goes on",
          "[stop]")
{
    test::TempDir dir;
    const auto caseDir = barCase(dir.path());
    const auto controlDict = caseDir / "system" / "controlDict";
    const auto log = dir.path() / "log";
    BackgroundSolver solver(caseDir, {"-set", "endTime=1"}, log); // far beyond the test
    solver.waitForOutputs(2);
    test::setEntry(controlDict, "stopAt", "writenow");
    // controlDict is looked at every second: after 2.5 s the edit was read, and rejected.
    std::this_thread::sleep_for(std::chrono::milliseconds(2500));
    REQUIRE(solver.running());
    {
        const std::string text = test::fileText(log);
        INFO(text);
        CHECK(text.find("WARNING: system/controlDict changed but is not valid: the run goes on "
                        "(stopAt endTime)") != std::string::npos);
        CHECK(text.find("unknown value 'writenow' for 'stopAt'") != std::string::npos);
        CHECK(text.find("Valid values for 'stopAt': endTime, writeNow") != std::string::npos);
    }
    test::setEntry(controlDict, "stopAt", "writeNow");
    const int status = solver.wait();
    const std::string text = test::fileText(log);
    INFO(text);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == stoppedExitCode);
    CHECK(text.find("Stopped     by stopAt writeNow") != std::string::npos);
    const auto summary = summaryOf(caseDir);
    CHECK(summary.at("status") == "stopped");
    CHECK(summary.at("stoppedBy") == "stopAt writeNow");
    CHECK(test::lastOutput(caseDir).fieldData.at("TimeValue").values.at(0) ==
          summary.at("time").get<double>());

    // Still there at the restart, it stops the run at once, at the level restored; set back to
    // endTime, the run goes on.
    const std::vector<std::string> restart{"-set", "controlDict.startFrom=latestTime", "-set",
                                           "endTime=1", "-set", "controlDict.maxSteps=100"};
    REQUIRE(test::runSolver(caseDir, restart) == stoppedExitCode);
    CHECK(summaryOf(caseDir).at("steps") == 0);
    test::setEntry(controlDict, "stopAt", "endTime");
    REQUIRE(test::runSolver(caseDir, restart) == 0);
    CHECK(summaryOf(caseDir).at("status") == "finished");
    CHECK(summaryOf(caseDir).at("steps") == 100);
}

TEST_CASE("startFrom startTime with startTime T continues from the output written at T",
          "[restart][stop]")
{
    test::TempDir one;
    test::TempDir two;
    const auto whole = test::copyTutorial("bar1D/dykaBar", one.path());
    const auto split = test::copyTutorial("bar1D/dykaBar", two.path());
    for (const auto& dir : {whole, split})
    {
        test::setEntry(dir / "system" / "controlDict", "writeInterval", "2e-4");
        test::setEntry(dir / "system" / "controlDict", "endTime", "1.5e-3");
        REQUIRE(test::runParticles(dir) == 0);
        REQUIRE(test::runSolver(dir) == 0);
    }
    const double wholeSteps = test::summaryValue(whole, "steps");

    // A time that was not written: the error lists those that were.
    test::setEntry(split / "system" / "controlDict", "startTime", "5e-4");
    std::string output;
    CHECK(test::runProcess("sphSolid", {"-case", split.string()}, &output) == 1);
    INFO(output);
    CHECK(output.find("system/controlDict") != std::string::npos);
    CHECK(output.find("no output was written at startTime 0.0005") != std::string::npos);
    CHECK(output.find("Written times: 0, 0.0002, 0.0004, 0.0006, 0.0008, 0.001, 0.0012, "
                      "0.0014, 0.0015.") != std::string::npos);

    // A written time (not the latest): the run continues from it, and ends bit-identically.
    test::setEntry(split / "system" / "controlDict", "startTime", "6e-4");
    CHECK(test::runProcess("sphSolid", {"-case", split.string()}, &output) == 0);
    CHECK(output.find("Restart     from dykaBar_3.vtu at step") != std::string::npos);
    CHECK(output.find("(the 5 later outputs are removed: they are computed again)") !=
          std::string::npos);
    const double splitSteps = test::summaryValue(split, "steps");
    CHECK(splitSteps > 0.0);
    CHECK(splitSteps < wholeSteps);
    requireSameRun(whole, split);
}
