#include "core/DictionaryParser.hpp"
#include "support/TestSupport.hpp"

using namespace sph;
using sph::test::parse;
using sph::test::requireInputError;

TEST_CASE("entries: words, numbers, strings and their locations", "[parser]")
{
    const auto dict = parse("endTime 5e-3;\n"
                            "  name   \"two words\";\n"
                            "type gradF;\n"
                            "count -40;\n");
    REQUIRE(dict->entries().size() == 4);
    const Entry* endTime = dict->find("endTime");
    REQUIRE(endTime);
    REQUIRE(endTime->items().size() == 1);
    CHECK(endTime->items()[0].kind() == Item::Kind::Number);
    CHECK(endTime->items()[0].number() == 5e-3);
    CHECK(endTime->keyLocation().line == 1);
    CHECK(endTime->keyLocation().column == 1);
    CHECK(endTime->items()[0].location().column == 9);

    const Entry* name = dict->find("name");
    CHECK(name->items()[0].kind() == Item::Kind::String);
    CHECK(name->items()[0].text() == "two words");
    CHECK(name->keyLocation().line == 2);
    CHECK(name->keyLocation().column == 3);
    CHECK(name->items()[0].location().column == 10);

    CHECK(dict->find("type")->items()[0].kind() == Item::Kind::Word);
    CHECK(dict->find("count")->items()[0].number() == -40);
}

TEST_CASE("numbers are decimal only, other words stay words", "[parser]")
{
    const auto dict = parse("a 0x10; b inf; c nan; d 1.5e+2; e .5; f libX.so; g -;");
    CHECK(dict->find("a")->items()[0].kind() == Item::Kind::Word);
    CHECK(dict->find("b")->items()[0].kind() == Item::Kind::Word);
    CHECK(dict->find("c")->items()[0].kind() == Item::Kind::Word);
    CHECK(dict->find("d")->items()[0].number() == 150.0);
    CHECK(dict->find("e")->items()[0].number() == 0.5);
    CHECK(dict->find("f")->items()[0].text() == "libX.so");
    CHECK(dict->find("g")->items()[0].kind() == Item::Kind::Word);
}

TEST_CASE("sub-dictionaries nest and know their names", "[parser]")
{
    const auto dict = parse("ringA\n{\n    material { type neoHookean; mu 1; }\n}\n");
    const Entry* ring = dict->find("ringA");
    REQUIRE(ring->isDict());
    const Entry* material = ring->dict().find("material");
    REQUIRE(material->isDict());
    CHECK(material->dict().name() == "ringA/material");
    CHECK(material->dict().location().line == 3);
    CHECK(material->dict().location().column == 5);
    CHECK(material->dict().find("mu")->items()[0].number() == 1.0);
    CHECK(&material->dict().topLevel() == dict.get());
}

TEST_CASE("lists and vectors nest", "[parser]")
{
    const auto dict = parse("points ((0 0) (1 2.5));\nlibs (\"libA.so\" \"libB.so\");\nempty ();");
    const Item& points = dict->find("points")->items()[0];
    REQUIRE(points.isList());
    REQUIRE(points.items().size() == 2);
    CHECK(points.items()[1].items()[1].number() == 2.5);
    CHECK(points.location().column == 8);
    CHECK(points.location().length == 15);
    const Item& libs = dict->find("libs")->items()[0];
    CHECK(libs.items()[0].kind() == Item::Kind::String);
    CHECK(libs.items()[1].text() == "libB.so");
    CHECK(dict->find("empty")->items()[0].items().empty());
    CHECK(points.toText() == "((0 0) (1 2.5))");
}

TEST_CASE("comments are ignored and do not shift locations", "[parser]")
{
    const auto dict = parse("// a line comment\n"
                            "a 1; /* block\n"
                            "comment */ b 2; // trailing\n"
                            "c /* inline */ 3;\n"
                            "d 4;//x\n");
    CHECK(dict->find("a")->items()[0].number() == 1);
    CHECK(dict->find("b")->keyLocation().line == 3);
    CHECK(dict->find("b")->keyLocation().column == 12);
    CHECK(dict->find("c")->items()[0].number() == 3);
    CHECK(dict->find("c")->items()[0].location().column == 16);
    CHECK(dict->find("d")->items()[0].number() == 4);
}

TEST_CASE("variables copy values and dictionaries, scoped outwards", "[parser]")
{
    const auto dict = parse("mu 0.3571e6;\n"
                            "rubber { type neoHookean; mu $mu; kappa 1.67e6; }\n"
                            "ringA { material $rubber; }\n"
                            "ringB { velocity (1 0); speed $velocity; kind $ringA.material.type; }\n"
                            "outer { inner { x $mu; } }\n");
    const Dictionary& rubber = dict->find("rubber")->dict();
    CHECK(rubber.find("mu")->items()[0].number() == 0.3571e6);
    const Entry* material = dict->find("ringA")->dict().find("material");
    REQUIRE(material->isDict());
    CHECK(material->dict().name() == "ringA/material");
    CHECK(material->dict().find("kappa")->items()[0].number() == 1.67e6);
    CHECK(dict->find("ringB")->dict().find("speed")->items()[0].isList());
    CHECK(dict->find("ringB")->dict().find("kind")->items()[0].text() == "neoHookean");
    CHECK(dict->find("outer")->dict().find("inner")->dict().find("x")->items()[0].number() ==
          0.3571e6);
}

TEST_CASE("a variable statement merges a dictionary whose entries may then be overridden", "[parser]")
{
    const auto dict = parse("ringA { velocity (1 0); material { type neoHookean; } }\n"
                            "ringB { $ringA; velocity (-1 0); }\n");
    const Dictionary& ringB = dict->find("ringB")->dict();
    CHECK(ringB.find("velocity")->items()[0].items()[0].number() == -1);
    CHECK(ringB.find("material")->dict().name() == "ringB/material");
}

TEST_CASE("#include is relative to the including file", "[parser]")
{
    sph::test::TempDir dir;
    dir.write("system/controlDict", "#include \"../constant/common\"\nendTime $shared;\n");
    dir.write("constant/common", "shared 7;\n#include \"more/deeper\"\n");
    dir.write("constant/more/deeper", "deep 1;\n");
    const auto dict = DictionaryParser::parseFile(dir.path() / "system/controlDict",
                                                  "system/controlDict");
    CHECK(dict->find("endTime")->items()[0].number() == 7);
    CHECK(dict->find("deep")->items()[0].number() == 1);
    CHECK(dict->find("shared")->keyLocation().fileName() == "constant/common");
    CHECK(dict->find("deep")->keyLocation().fileName() == "constant/more/deeper");
}

// A UTF-8 byte-order mark (some Windows editors write one) is not part of the first key, and
// columns count from after it (issue 12 item 9).
TEST_CASE("a file starting with a UTF-8 byte-order mark reads as without it", "[parser]")
{
    sph::test::TempDir dir;
    dir.write("system/controlDict", "\xEF\xBB\xBF" "endTime 7;\n");
    const auto dict = DictionaryParser::parseFile(dir.path() / "system/controlDict",
                                                  "system/controlDict");
    REQUIRE(dict->find("endTime"));
    CHECK(dict->find("endTime")->items()[0].number() == 7);
    CHECK(dict->find("endTime")->keyLocation().column == 1);
}

TEST_CASE("#include errors: missing file, cycle, bad argument", "[parser][errors]")
{
    sph::test::TempDir dir;
    dir.write("a", "x 1;\n#include \"missing\"\n");
    requireInputError([&] { DictionaryParser::parseFile(dir.path() / "a", "a"); }, 2, 10,
                      "cannot open included file 'missing'");

    dir.write("b", "y 1;\n  #include \"c\"\n");
    dir.write("c", "#include \"b\"\n");
    const std::string text = requireInputError(
        [&] { DictionaryParser::parseFile(dir.path() / "b", "b"); }, 1, 10, "#include cycle");
    CHECK_THAT(text, Catch::Contains("b -> c -> b"));

    requireInputError([] { parse("#include missing\n"); }, 1, 10, "#include needs a quoted");
    requireInputError([] { parse("a 1;\n#inclde \"x\"\n"); }, 2, 1, "unknown directive");
}

TEST_CASE("syntax errors are reported at the exact line and column", "[parser][errors]")
{
    SECTION("undefined variable, with a suggestion")
    {
        const std::string text =
            requireInputError([] { parse("speed 3;\nv $sped;\n"); }, 2, 3, "undefined variable '$sped'");
        CHECK_THAT(text, Catch::Contains("Did you mean 'speed'?"));
    }
    SECTION("variable used before it is defined")
    {
        requireInputError([] { parse("a $b;\nb 1;\n"); }, 1, 3, "undefined variable '$b'");
    }
    SECTION("duplicate key names both places")
    {
        const std::string text = requireInputError([] { parse("a 1;\nb 2;\n  a 3;\n"); }, 3, 3,
                                                   "duplicate key 'a'");
        CHECK_THAT(text, Catch::Contains("testDict:1:1"));
    }
    SECTION("duplicate sub-dictionary")
    {
        requireInputError([] { parse("s { }\ns { }\n"); }, 2, 1, "duplicate key 's'");
    }
    SECTION("unterminated brace points at the opening brace")
    {
        requireInputError([] { parse("a 1;\nouter\n{\n  inner { b 2; }\n"); }, 3, 1,
                          "unterminated '{'");
    }
    SECTION("unterminated string points at the opening quote")
    {
        requireInputError([] { parse("a 1;\nname \"abc;\n"); }, 2, 6, "unterminated string");
    }
    SECTION("unterminated comment points at /*")
    {
        requireInputError([] { parse("a 1;\n  /* never closed\nb 2;\n"); }, 2, 3,
                          "unterminated comment");
    }
    SECTION("unterminated list")
    {
        requireInputError([] { parse("v (1 2;\n"); }, 1, 3, "unterminated '('");
    }
    SECTION("missing ';' before the next line")
    {
        const std::string text =
            requireInputError([] { parse("endTime 0.005\nwriteInterval 1e-4;\n"); }, 1, 14,
                              "missing ';' after the value of 'endTime'");
        CHECK_THAT(text, Catch::Contains("^"));
    }
    SECTION("missing ';' before '}'")
    {
        requireInputError([] { parse("s { type gradF }\n"); }, 1, 15,
                          "missing ';' after the value of 'type'");
    }
    SECTION("missing ';' at the end of the file")
    {
        requireInputError([] { parse("a 1;\nb 2"); }, 2, 4, "missing ';'");
    }
    SECTION("unexpected closing brace")
    {
        requireInputError([] { parse("a 1;\n}\n"); }, 2, 1, "unexpected '}'");
    }
    SECTION("entry without a value")
    {
        requireInputError([] { parse("a;\n"); }, 1, 1, "has no value");
    }
    SECTION("a value cannot start with '{' after items")
    {
        requireInputError([] { parse("a 1 { }\n"); }, 1, 4, "missing ';'");
    }
    SECTION("a key must be a word")
    {
        requireInputError([] { parse("(1 2);\n"); }, 1, 1, "expected a key");
    }
    SECTION("merging a value is an error")
    {
        requireInputError([] { parse("a 1;\nb { $a; }\n"); }, 2, 5, "merges a dictionary");
    }
    SECTION("a dictionary cannot be part of a value")
    {
        requireInputError([] { parse("d { }\nb 1 $d;\n"); }, 2, 5, "is a dictionary");
    }
}

TEST_CASE("the formatted message quotes the line with a caret under the value", "[parser]")
{
    try
    {
        parse("x 1;\ny $z;\n", "system/sphSchemes");
        FAIL("no error");
    }
    catch (const InputError& error)
    {
        const std::string text = error.what();
        CHECK_THAT(text, Catch::StartsWith("--> "));
        CHECK_THAT(text, Catch::Contains("system/sphSchemes:2:3: undefined variable '$z'"));
        CHECK_THAT(text, Catch::Contains("    y $z;\n      ^~\n"));
    }
}

TEST_CASE("an error in a huge line or about a huge key is not echoed whole", "[parser][errors]")
{
    // A key of 100 000 characters with its ';' missing: the message quotes the key and the
    // source line holds it; both are cut to a window around the error (issue 12 item 9).
    const std::string key(100000, 'k');
    try
    {
        DictionaryParser::parseString(key + " 1\nnext 2;\n", "huge");
        FAIL("no error");
    }
    catch (const InputError& error)
    {
        const std::string text = error.what();
        CHECK(text.size() < 3000);
        CHECK_THAT(text, Catch::Contains("missing ';'"));
        CHECK_THAT(text, Catch::Contains("characters ...]"));
        CHECK_THAT(text, Catch::Contains("huge:1:"));
    }
    // A long line of brackets: the source line is shown as a window around the error column.
    try
    {
        DictionaryParser::parseString("a " + std::string(5000, '(') + ";\n", "brackets");
        FAIL("no error");
    }
    catch (const InputError& error)
    {
        CHECK(std::string(error.what()).size() < 1500);
    }
}

namespace
{

// Parses `dir`/main, which includes `included`; returns the formatted error.
std::string includeError(const sph::test::TempDir& dir, const std::string& included)
{
    dir.write("main", "x 1;\n#include \"" + included + "\"\n");
    try
    {
        DictionaryParser::parseFile(dir.path() / "main", "main");
    }
    catch (const InputError& error)
    {
        return error.what();
    }
    FAIL("no error");
    return {};
}

} // namespace

TEST_CASE("an included file that is not a dictionary is quoted by its offending line only",
          "[parser][errors]")
{
    // #include may name any readable file (issue 12 item 2): the message must not echo the
    // key on the line above nor the word on the line below, only the line it points at.
    sph::test::TempDir dir;
    std::string notes = "password-notes\n"
                        "the offending line holds the value of the key above\n"
                        "hunter2 is on the third line\n";
    for (int i = 4; i <= 40; ++i)
    {
        notes += "line " + std::to_string(i) + " of the notes\n";
    }
    dir.write("notes.txt", notes);
    const std::string text = includeError(dir, "notes.txt");
    CHECK_THAT(text, Catch::Contains("notes.txt:2:52: missing ';' after this value"));
    CHECK_THAT(text, Catch::Contains("    the offending line holds the value of the key above\n"));
    CHECK_THAT(text, Catch::Contains("(found a word on line 3 next)"));
    CHECK_THAT(text, !Catch::Contains("password-notes"));
    CHECK_THAT(text, !Catch::Contains("hunter2"));
    CHECK_THAT(text, !Catch::Contains("line 4"));

    // One long line (as /proc/self/environ is): nothing beyond the 120-character window.
    dir.write("environ", "HOME=/root" + std::string(1, '\0') + "SECRET=" + std::string(3000, 's') +
                             " and more\n");
    const std::string environ = includeError(dir, "environ");
    CHECK_THAT(environ, Catch::Contains("missing ';' after this value"));
    CHECK(environ.size() < 600);
    CHECK_THAT(environ, !Catch::Contains("HOME=/root"));
}

TEST_CASE("binary content is shown escaped, valid UTF-8 as it is", "[parser][errors]")
{
    sph::test::TempDir dir;
    dir.write("blob", std::string("\x7f"
                                  "ELF\x02\x01\x01",
                                  7) +
                          std::string(3, '\0') +
                          "\xff\xfe\x80 \xc3"
                          "A \xce\xbb }\n");
    const std::string text = includeError(dir, "blob");
    CHECK_THAT(text, Catch::Contains("\\x7fELF\\x02\\x01\\x01\\x00\\x00\\x00\\xff\\xfe\\x80"));
    CHECK_THAT(text, Catch::Contains("missing ';' after the value of '\\x7fELF"));
    CHECK_THAT(text, Catch::Contains("\\xc3A"));   // a cut sequence: the lead byte escaped
    CHECK_THAT(text, Catch::Contains("\xce\xbb")); // λ stays readable
    CHECK(text.find('\xff') == std::string::npos);
    CHECK(text.find('\x80') == std::string::npos);
}
