// The command line's help text (issue 12, item 16: it said options take one dash, then listed
// them with two).
#include "core/CommandLine.hpp"
#include "core/InputError.hpp"
#include "support/TestSupport.hpp"

#include <fstream>

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
