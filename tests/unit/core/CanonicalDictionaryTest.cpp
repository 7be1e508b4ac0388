// The canonical form of a dictionary (core/CanonicalDictionary): what
// constant/particles.vtu records about the system/particlesDict that made it (issue 32 item 1).
#include "core/CanonicalDictionary.hpp"
#include "core/DictionaryParser.hpp"
#include "support/TestSupport.hpp"

using namespace sph;

namespace
{

std::vector<std::string> linesOf(const std::string& text)
{
    return canonicalLines(*DictionaryParser::parseString(text, "system/particlesDict"));
}

} // namespace

TEST_CASE("canonical dictionary: keeps the meaning and drops the layout", "[canonical]")
{
    const auto lines = linesOf("// a bar\nbar\n{\n    type line;  start 0; end 0.1333;\n"
                               "    n 40; centre (0 1e-3); name \"x y\"; empty {}\n}\n");
    CHECK(lines == std::vector<std::string>{"bar.type line", "bar.start 0", "bar.end 0.1333",
                                            "bar.n 40", "bar.centre (0 0.001)", "bar.name \"x y\"",
                                            "bar.empty {}"});
    // Comments, layout and the spelling of a number do not change it.
    CHECK(lines == linesOf("bar { type line; start 0.0; end 1.333e-1; n 4e1; /* c */ "
                           "centre (0 0.001); name \"x y\"; empty { } }"));
    // A value or the order of the bodies does.
    CHECK(linesOf("a { n 40; } b { n 2; }") != linesOf("a { n 80; } b { n 2; }"));
    CHECK(linesOf("a { n 40; } b { n 2; }") != linesOf("b { n 2; } a { n 40; }"));
    // $name copies are resolved: the body holds the value it uses.
    CHECK(linesOf("dx 2e-3;\nbar { spacing $dx; }") ==
          std::vector<std::string>{"dx 0.002", "bar.spacing 0.002"});
}
