// The command line's help text (issue 12, item 16: it said options take one dash, then listed
// them with two); -h, the recorded command line and the git revision (issue 32 item 8).
#include "core/CommandLine.hpp"
#include "core/InputError.hpp"
#include "support/TestSupport.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace sph;

TEST_CASE("the help text lists the options with one dash, as they are typed", "[commandLine]")
{
    CommandLine line("sphTest", "a test program");
    line.enableModelOptions(true, true, true);
    line.options().add_options()("threads", "a program's own option");
    const std::string text = line.usage();
    CHECK_THAT(text, Catch::Contains("Options take one dash"));
    CHECK_THAT(text, Catch::Contains("\n   -case DIR"));
    CHECK_THAT(text, Catch::Contains("\n   -listTypes"));
    CHECK_THAT(text, Catch::Contains("\n   -threads"));
    CHECK_THAT(text, !Catch::Contains("--"));
}

// -case naming a file, not a folder: said "does not exist" (issue 12 item 9).
TEST_CASE("the case option naming a file says it is a file, a missing folder that it does not exist",
          "[commandLine]")
{
    test::TempDir dir;
    const auto file = dir.path() / "controlDict";
    std::ofstream(file) << "endTime 1;\n";
    const auto messageFor = [](const std::string& caseDir)
    {
        CommandLine line("sphTest", "a test program");
        line.enableModelOptions(true, true, true);
        const std::vector<const char*> argv{"sphTest", "-case", caseDir.c_str()};
        try
        {
            line.parse(static_cast<int>(argv.size()), argv.data());
        }
        catch (const InputError& error)
        {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    CHECK_THAT(messageFor(file.string()), Catch::Contains("is a file, not a folder"));
    CHECK_THAT(messageFor((dir.path() / "missing").string()), Catch::Contains("does not exist"));
}

// -h is -help (issue 32 item 8): users try it first.
TEST_CASE("-h prints the help, as -help does", "[commandLine]")
{
    const auto helpOf = [](const char* option)
    {
        CommandLine line("sphTest", "a test program");
        const std::vector<const char*> argv{"sphTest", option};
        std::ostringstream out;
        std::streambuf* saved = std::cout.rdbuf(out.rdbuf());
        bool goOn = true;
        try
        {
            goOn = line.parse(static_cast<int>(argv.size()), argv.data());
        }
        catch (...)
        {
            std::cout.rdbuf(saved);
            throw;
        }
        std::cout.rdbuf(saved);
        CHECK(!goOn); // the program exits 0 at once
        return out.str();
    };
    const std::string help = helpOf("-help");
    CHECK_THAT(help, Catch::Contains("Usage: sphTest"));
    CHECK_THAT(help, Catch::Contains("(also -h)"));
    CHECK(helpOf("-h") == help);
    CHECK(helpOf("--help") == help);
}

// summary.json records the command line so that the run can be made again: as a shell takes
// it back, quoted where needed.
TEST_CASE("the process's command line is recorded, quoted for the shell", "[commandLine]")
{
    test::TempDir dir;
    const auto caseDir = dir.path() / "my case";
    std::filesystem::create_directories(caseDir);
    CommandLine line("sphTest", "a test program");
    const std::string path = caseDir.string();
    const std::vector<const char*> argv{"/some/where/sphTest", "-case", path.c_str(), "-set",
                                        "endTime=1e-3",        "-set",
                                        "bodies.plate.material={ type linearElastic; E 1e6; }",
                                        "-set",                "name=it's"};
    REQUIRE(line.parse(static_cast<int>(argv.size()), argv.data()));
    CHECK(processCommandLine() ==
          "sphTest -case '" + path +
              "' -set endTime=1e-3 -set 'bodies.plate.material={ type linearElastic; E 1e6; }' "
              "-set 'name=it'\\''s'");
}

TEST_CASE("the version names the build's git revision", "[commandLine]")
{
    const std::string revision = gitRevision();
    CHECK(!revision.empty());
    // A build from a git checkout knows its revision (CI builds from a clean clone).
    if (std::filesystem::exists(std::filesystem::path(SPH_SOURCE_DIR) / ".git"))
    {
        CHECK(revision != "unknown");
    }
}
