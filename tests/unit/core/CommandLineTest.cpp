// The command line's help text (issue 12, item 16: it said options take one dash, then listed
// them with two).
#include "core/CommandLine.hpp"
#include "support/TestSupport.hpp"

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
