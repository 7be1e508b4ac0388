// The canonical form and digest of a dictionary (core/DictionaryDigest, core/Sha256): what
// constant/particles.vtu records about the system/particlesDict that made it (issue 32 item 1).
#include "core/DictionaryDigest.hpp"
#include "core/DictionaryParser.hpp"
#include "core/Sha256.hpp"
#include "support/TestSupport.hpp"

using namespace sph;

namespace
{

std::vector<std::string> linesOf(const std::string& text)
{
    return canonicalLines(*DictionaryParser::parseString(text, "system/particlesDict"));
}

} // namespace

TEST_CASE("digest: sha256 gives the FIPS 180-4 test vectors", "[digest]")
{
    CHECK(sha256Hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    CHECK(sha256Hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    // 56 bytes: the padding's length no longer fits the first block.
    CHECK(sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
          "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
    CHECK(sha256Hex(std::string(1000, 'a')) ==
          "41edece42d63e8d9bf515a9ba6932e1c20cbc9f5a5d134645adb5db1b9737ea3");
}

TEST_CASE("digest: the canonical form keeps the meaning and drops the layout", "[digest]")
{
    const auto lines = linesOf("// a bar\nbar\n{\n    type line;  start 0; end 0.1333;\n"
                               "    n 40; centre (0 1e-3); name \"x y\"; empty {}\n}\n");
    CHECK(lines == std::vector<std::string>{"bar.type line", "bar.start 0", "bar.end 0.1333",
                                            "bar.n 40", "bar.centre (0 0.001)", "bar.name \"x y\"",
                                            "bar.empty {}"});
    // Comments, layout and the spelling of a number do not change it.
    CHECK(canonicalDigest(lines) ==
          canonicalDigest(linesOf("bar { type line; start 0.0; end 1.333e-1; n 4e1; /* c */ "
                                  "centre (0 0.001); name \"x y\"; empty { } }")));
    // A value or the order of the bodies does.
    CHECK(canonicalDigest(linesOf("a { n 40; } b { n 2; }")) !=
          canonicalDigest(linesOf("a { n 80; } b { n 2; }")));
    CHECK(canonicalDigest(linesOf("a { n 40; } b { n 2; }")) !=
          canonicalDigest(linesOf("b { n 2; } a { n 40; }")));
    // $name copies are resolved: the body holds the value it uses.
    CHECK(linesOf("dx 2e-3;\nbar { spacing $dx; }") ==
          std::vector<std::string>{"dx 0.002", "bar.spacing 0.002"});
}

TEST_CASE("digest: a digest is the SHA-256 of the canonical lines", "[digest]")
{
    CHECK(canonicalDigest({"bar.n 40"}) == sha256Hex("bar.n 40\n"));
}
