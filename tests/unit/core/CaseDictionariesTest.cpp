#include "core/CaseDictionaries.hpp"
#include "support/TestSupport.hpp"

using namespace sph;
using sph::test::requireInputError;

namespace
{

void writeCase(const sph::test::TempDir& dir)
{
    dir.write("system/controlDict", "endTime 5e-3;\ncourant 0.01;\n");
    dir.write("system/sphSchemes",
              "dimension 1;\nstabilisation { type none; }\nkernel { type cubicSpline; }\n");
    dir.write("constant/bodies", "bar { material { type linearElastic; E 3e4; } }\n");
}

} // namespace

TEST_CASE("set overrides replace, adds and finds the right file", "[case]")
{
    sph::test::TempDir dir;
    writeCase(dir);
    CaseDictionaries dicts(dir.path());
    dicts.read({"controlDict", "sphSchemes", "bodies"});
    dicts.applySets({"endTime=1e-3", "stabilisation.type=gradF", "stabilisation.beta=(0.1)",
                     "controlDict.startFrom=latestTime", "bar.material.E=2e4",
                     "sphSchemes/kernel/hOverDx=2"});
    const Dictionary& control = dicts.get("controlDict");
    CHECK(control.find("endTime")->items()[0].number() == 1e-3);
    CHECK(control.find("startFrom")->items()[0].text() == "latestTime");
    const Dictionary& schemes = dicts.get("sphSchemes");
    CHECK(schemes.find("stabilisation")->dict().find("type")->items()[0].text() == "gradF");
    CHECK(schemes.find("stabilisation")->dict().find("beta")->items()[0].isList());
    CHECK(schemes.find("kernel")->dict().find("hOverDx")->items()[0].number() == 2);
    CHECK(dicts.get("bodies").find("bar")->dict().find("material")->dict().find("E")->items()[0].number() == 2e4);
    // The overridden value points into the command line.
    CHECK(control.find("endTime")->items()[0].location().fileName() == "command line");
    CHECK(control.find("endTime")->items()[0].location().column == 14);
}

TEST_CASE("a set value in braces replaces or adds a whole dictionary", "[case]")
{
    sph::test::TempDir dir;
    writeCase(dir);
    CaseDictionaries dicts(dir.path());
    dicts.read({"controlDict", "sphSchemes", "bodies"});
    dicts.applySets({"bar.material={ type neoHookean; mu 1e5; kappa 3e5; rho 10; }",
                     "sphSchemes.contact={type none;}"});
    const Dictionary& material = dicts.get("bodies").find("bar")->dict().find("material")->dict();
    CHECK(material.keys() == std::vector<std::string>{"type", "mu", "kappa", "rho"});
    CHECK(material.find("type")->items()[0].text() == "neoHookean");
    CHECK(material.find("E") == nullptr); // the old entries are gone
    // Locations point into the command line: "-set bar.material={ type" -> 'type' at column 21.
    CHECK(material.find("type")->keyLocation().fileName() == "command line");
    CHECK(material.find("type")->keyLocation().column == 21);
    CHECK(dicts.get("sphSchemes").find("contact")->dict().find("type")->items()[0].text() == "none");
}

TEST_CASE("set override errors point into the command line", "[case][errors]")
{
    sph::test::TempDir dir;
    writeCase(dir);
    CaseDictionaries dicts(dir.path());
    dicts.read({"controlDict", "sphSchemes", "bodies"});
    SECTION("no '='")
    {
        requireInputError([&] { dicts.applySets({"endTime"}); }, 1, 6, "-set needs the form");
    }
    SECTION("unknown top-level key with suggestion and the file-prefix hint")
    {
        const std::string text = requireInputError([&] { dicts.applySets({"endTme=1"}); }, 1, 6,
                                                   "no case dictionary has a top-level key 'endTme'");
        CHECK_THAT(text, Catch::Contains("Did you mean 'endTime'?"));
        CHECK_THAT(text, Catch::Contains("-set controlDict.endTme=1"));
    }
    SECTION("missing intermediate dictionary")
    {
        const std::string text = requireInputError(
            [&] { dicts.applySets({"stabilsation.type=gradF"}); }, 1, 6, "no case dictionary");
        CHECK_THAT(text, Catch::Contains("Did you mean 'stabilisation'?"));
    }
    SECTION("setting a whole dictionary")
    {
        requireInputError([&] { dicts.applySets({"stabilisation=gradF"}); }, 1, 6,
                          "'stabilisation' is a dictionary");
    }
    SECTION("an unclosed brace")
    {
        requireInputError([&] { dicts.applySets({"bar.material={ type x;"}); }, 1, 19,
                          "the '{' of this value is not closed");
    }
    SECTION("a syntax error inside braces points at it")
    {
        requireInputError([&] { dicts.applySets({"bar.material={ type (x; }"}); }, 1, 26, "");
    }
    SECTION("bad value syntax")
    {
        requireInputError([&] { dicts.applySets({"endTime=(1"}); }, 1, 14, "unterminated '('");
    }
}

TEST_CASE("a missing case file says what a case holds", "[case][errors]")
{
    sph::test::TempDir dir;
    CaseDictionaries dicts(dir.path());
    try
    {
        dicts.read({"controlDict"});
        FAIL("no error");
    }
    catch (const InputError& error)
    {
        CHECK_THAT(error.message(), Catch::Contains("cannot find system/controlDict"));
        CHECK_THAT(error.what(), Catch::Contains("copy a tutorial case"));
    }
}

// An OpenFOAM `FoamFile { }` header is accepted and ignored (issue 12 item 14): the bodies file
// keeps one body, not a second one named FoamFile.
TEST_CASE("an OpenFOAM FoamFile header is ignored", "[case]")
{
    sph::test::TempDir dir;
    writeCase(dir);
    const std::string header =
        "FoamFile\n{\n    version 2.0;\n    format ascii;\n    class dictionary;\n}\n";
    dir.write("constant/bodies",
              header + "bar { material { type linearElastic; E 3e4; } }\n");
    dir.write("system/controlDict", header + "endTime 5e-3;\ncourant 0.01;\n");
    CaseDictionaries dicts(dir.path());
    dicts.read({"controlDict", "sphSchemes", "bodies"});
    CHECK(dicts.get("bodies").keys() == std::vector<std::string>{"bar"});
    CHECK(dicts.get("controlDict").find("FoamFile") == nullptr);
    CHECK(dicts.get("controlDict").find("endTime")->items()[0].number() == 5e-3);
}

// A -set for a file the application does not take as input changed nothing and said nothing:
// `sphSolid -set particlesDict.bar.n=80` ran the old particles, and `-set bar.n=80` suggested
// `bodies.bar.n=80` (issue 32 item 1).
TEST_CASE("particle record: a -set aimed at a file another application reads names it",
          "[case][errors]")
{
    sph::test::TempDir dir;
    writeCase(dir);
    dir.write("system/particlesDict", "bar { type line; start 0; end 0.1333; n 40; }\n");
    CaseDictionaries dicts(dir.path());
    dicts.read({"controlDict", "sphSchemes", "bodies"}, {"particlesDict"});
    SECTION("prefixed with the file sphSolid only checks against")
    {
        const std::string text = requireInputError(
            [&] { dicts.applySets({"particlesDict.bar.n=80"}, {"particlesDict"}); }, 1, 6,
            "-set: system/particlesDict is read by sphParticles, not by sphSolid");
        CHECK_THAT(text,
                   Catch::Contains("sphParticles -set particlesDict.bar.n=80 (then run sphSolid)"));
    }
    SECTION("a path written whole only in that file, not the bodies' bar")
    {
        const std::string text = requireInputError(
            [&] { dicts.applySets({"bar.n=80"}, {"particlesDict"}); }, 1, 6,
            "-set: system/particlesDict is read by sphParticles, not by sphSolid");
        CHECK_THAT(text, Catch::Contains("sphParticles -set bar.n=80"));
        CHECK_THAT(text, !Catch::Contains("bodies.bar.n"));
    }
    SECTION("a path of the bodies is set in the bodies")
    {
        dicts.applySets({"bar.material.E=2e4"}, {"particlesDict"});
        const Dictionary& material =
            dicts.get("bodies").find("bar")->dict().find("material")->dict();
        CHECK(material.find("E")->items()[0].number() == 2e4);
        CHECK(dicts.get("particlesDict").find("bar")->dict().find("material") == nullptr);
    }
    SECTION("a file the application does not read at all")
    {
        requireInputError([&] { dicts.applySets({"studyDict.levels.n=2"}); }, 1, 6,
                          "-set: system/studyDict is read by sphStudy, not by sphSolid");
    }
    SECTION("an ambiguous key suggests the file that holds the whole path")
    {
        const std::string text =
            requireInputError([&] { dicts.applySets({"bar.n=80"}); }, 1, 6,
                              "-set key 'bar' is ambiguous: it is in bodies, particlesDict");
        CHECK_THAT(text, Catch::Contains("Prefix the file: -set particlesDict.bar.n=80"));
        CHECK_THAT(text, !Catch::Contains("bodies.bar.n"));
    }
}
