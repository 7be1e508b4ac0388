#include "core/Schema.hpp"
#include "support/TestSupport.hpp"

using namespace sph;
using sph::test::parse;
using sph::test::requireInputError;

namespace
{

Schema materialSchema()
{
    return Schema()
        .add(Key::real("mu", "shear modulus [Pa]").positive())
        .add(Key::real("kappa", "bulk modulus [Pa]").positive())
        .add(Key::real("nu", "Poisson's ratio").range(-1.0, 0.5, false, false).defaultValue("0.3"))
        .add(Key::integer("n", "a count").min(1).defaultValue("4"))
        .add(Key::boolean("flag", "a switch").defaultValue("false"))
        .add(Key::word("mode", "a mode").choices({"fast", "exact"}).defaultValue("exact"))
        .add(Key::vector("velocity", "initial velocity [m/s]").defaultValue("0"))
        .add(Key::vectorList("points", "probe points").optional())
        .add(Key::stringList("libs", "libraries").defaultValue("()"))
        .add(Key::dict("region", "where").optional());
}

ValidationContext context(int dimension = 2)
{
    ValidationContext c;
    c.dimension = dimension;
    c.label = "neoHookean";
    return c;
}

} // namespace

TEST_CASE("schema: typed values and defaults", "[schema]")
{
    const auto dict = parse("type neoHookean;\nmu 1e6;\nkappa 2e6;\nflag yes;\n"
                            "velocity (1 -2);\npoints ((0 0) (1 1));\nlibs (\"a.so\" b.so);\n"
                            "region { type box; }\n");
    const Params p = materialSchema().validate(*dict, context());
    CHECK(p.real("mu") == 1e6);
    CHECK(p.real("nu") == 0.3);
    CHECK_FALSE(p.given("nu"));
    CHECK(p.given("mu"));
    CHECK(p.integer("n") == 4);
    CHECK(p.boolean("flag"));
    CHECK(p.word("mode") == "exact");
    CHECK(p.vector("velocity") == std::vector<double>{1, -2});
    CHECK(p.vectorList("points").size() == 2);
    CHECK(p.stringList("libs") == std::vector<std::string>{"a.so", "b.so"});
    CHECK(p.has("region"));
    CHECK(p.dict("region").find("type"));
    CHECK(p.location("mu").line == 2);
}

TEST_CASE("schema: a number default fills every vector component", "[schema]")
{
    const auto dict = parse("mu 1;\nkappa 1;\n");
    CHECK(materialSchema().validate(*dict, context(3)).vector("velocity") ==
          std::vector<double>{0, 0, 0});
    CHECK(materialSchema().validate(*dict, context(1)).vector("velocity") ==
          std::vector<double>{0});
}

TEST_CASE("schema: optional keys without default are absent", "[schema]")
{
    const auto dict = parse("mu 1;\nkappa 1;\n");
    const Params p = materialSchema().validate(*dict, context());
    CHECK_FALSE(p.has("points"));
    CHECK_THROWS_AS(p.vectorList("points"), std::logic_error);
}

TEST_CASE("schema: errors name the key, the place and the valid choices", "[schema][errors]")
{
    const Schema schema = materialSchema();
    SECTION("missing required key lists what the model needs")
    {
        const auto dict = parse("ringA\n{\n    material\n    {\n        kappa 1;\n    }\n}\n",
                                "constant/bodies");
        const Dictionary& material = dict->find("ringA")->dict().find("material")->dict();
        const std::string text = requireInputError([&] { schema.validate(material, context()); },
                                                   3, 5, "missing required key 'mu' in 'ringA/material'");
        CHECK_THAT(text, Catch::Contains("(neoHookean needs: kappa, mu)"));
    }
    SECTION("unknown key with did-you-mean")
    {
        const auto dict = parse("mu 1;\nkappa 1;\n  nuu 0.3;\n");
        const std::string text = requireInputError([&] { schema.validate(*dict, context()); }, 3,
                                                   3, "unknown key 'nuu'");
        CHECK_THAT(text, Catch::Contains("Did you mean 'nu'?"));
        CHECK_THAT(text, Catch::Contains("neoHookean accepts: flag, kappa, libs, mode, mu, n, nu"));
    }
    SECTION("a typo of a required key is reported as unknown, with the suggestion")
    {
        const auto dict = parse("mue 1;\nkappa 1;\n");
        const std::string text = requireInputError([&] { schema.validate(*dict, context()); }, 1,
                                                   1, "unknown key 'mue'");
        CHECK_THAT(text, Catch::Contains("Did you mean 'mu'?"));
    }
    SECTION("wrong type")
    {
        const auto dict = parse("mu soft;\nkappa 1;\n");
        requireInputError([&] { schema.validate(*dict, context()); }, 1, 4,
                          "'mu' in 'testDict' must be a real, found word 'soft'");
    }
    SECTION("out of range, open interval")
    {
        const auto dict = parse("mu 1;\nkappa 1;\nnu 0.5;\n");
        requireInputError([&] { schema.validate(*dict, context()); }, 3, 4,
                          "nu = 0.5 must lie in (-1, 0.5)");
    }
    SECTION("positive")
    {
        const auto dict = parse("mu 0;\nkappa 1;\n");
        requireInputError([&] { schema.validate(*dict, context()); }, 1, 4,
                          "mu = 0 must lie in (0, inf)");
    }
    SECTION("integer must be whole")
    {
        const auto dict = parse("mu 1;\nkappa 1;\nn 2.5;\n");
        requireInputError([&] { schema.validate(*dict, context()); }, 3, 3, "must be a whole number");
    }
    SECTION("bool")
    {
        const auto dict = parse("mu 1;\nkappa 1;\nflag maybe;\n");
        requireInputError([&] { schema.validate(*dict, context()); }, 3, 6, "must be true or false");
    }
    SECTION("word choices")
    {
        const auto dict = parse("mu 1;\nkappa 1;\nmode fsat;\n");
        const std::string text = requireInputError([&] { schema.validate(*dict, context()); }, 3,
                                                   6, "unknown value 'fsat' for 'mode'");
        CHECK_THAT(text, Catch::Contains("Valid values for 'mode': exact, fast"));
        CHECK_THAT(text, Catch::Contains("Did you mean 'fast'?"));
    }
    SECTION("vector of the wrong dimension")
    {
        const auto dict = parse("mu 1;\nkappa 1;\nvelocity (1 2 3);\n");
        const std::string text = requireInputError([&] { schema.validate(*dict, context(2)); }, 3,
                                                   10, "must be a vector of 2 numbers");
        CHECK_THAT(text, Catch::Contains("The case is 2D"));
    }
    SECTION("vector component not a number")
    {
        const auto dict = parse("mu 1;\nkappa 1;\nvelocity (1 a);\n");
        requireInputError([&] { schema.validate(*dict, context(2)); }, 3, 13,
                          "a vector component must be a number");
    }
    SECTION("several items where one is expected hints at a missing ';'")
    {
        const auto dict = parse("mu 1 kappa 1;\n");
        const std::string text = requireInputError([&] { schema.validate(*dict, context()); }, 1,
                                                   6, "'mu' takes one value");
        CHECK_THAT(text, Catch::Contains("Is a ';' missing after 1?"));
    }
    SECTION("dictionary where a value is expected")
    {
        const auto dict = parse("mu { }\nkappa 1;\n");
        requireInputError([&] { schema.validate(*dict, context()); }, 1, 1,
                          "must be a real, found a dictionary");
    }
    SECTION("value where a dictionary is expected")
    {
        const auto dict = parse("mu 1;\nkappa 1;\nregion box;\n");
        requireInputError([&] { schema.validate(*dict, context()); }, 3, 8,
                          "must be a dictionary { ... }");
    }
}

TEST_CASE("schema: reading an undeclared key is a programming error", "[schema]")
{
    const auto dict = parse("mu 1;\nkappa 1;\n");
    const Params p = materialSchema().validate(*dict, context());
    try
    {
        (void)p.real("mue");
        FAIL("no error");
    }
    catch (const std::logic_error& error)
    {
        CHECK_THAT(error.what(), Catch::Contains("undeclared key 'mue'"));
        CHECK_THAT(error.what(), Catch::Contains("Did you mean 'mu'?"));
    }
    CHECK_THROWS_AS(p.integer("mu"), std::logic_error); // declared as real
}

TEST_CASE("schema: Params::fail points at the value", "[schema]")
{
    const auto dict = parse("mu 1;\nkappa   7;\n");
    const Params p = materialSchema().validate(*dict, context());
    requireInputError([&] { p.fail("kappa", "kappa must exceed mu"); }, 2, 9, "kappa must exceed mu");
}

TEST_CASE("schema: describe() lists every key with type, default, range and doc", "[schema]")
{
    const auto lines = materialSchema().describe();
    REQUIRE(lines.size() == 10);
    CHECK(lines[0] == "mu  (real, required, range (0, inf))  shear modulus [Pa]");
    CHECK(lines[2] == "nu  (real, default 0.3, range (-1, 0.5))  Poisson's ratio");
    CHECK_THAT(lines[5], Catch::Contains("one of: exact fast"));
}

TEST_CASE("schema: body keys are checked against the case's bodies", "[schema]")
{
    const Schema schema = Schema()
                              .add(Key::body("body", "only this body").optional())
                              .add(Key::bodyList("bodies", "these bodies").defaultValue("()"));
    ValidationContext c = context();
    c.bodies = {"ringA", "ringB", "wall"};
    const auto dict = parse("body ringB;\nbodies (wall ringA);\n");
    const Params p = schema.validate(*dict, c);
    CHECK(p.word("body") == "ringB");
    CHECK(p.bodyIndex("body") == 1);
    CHECK(p.bodyIndices("bodies") == std::vector<std::size_t>{2, 0});
    CHECK(schema.describe()[0] == "body  (body name, optional)  only this body");
    CHECK(schema.describe()[1] == "bodies  (list of body names, default ())  these bodies");

    // The offending word itself, the bodies and the closest one.
    const auto typo = parse("bodies (ringA rinB);\n");
    const std::string text = requireInputError([&] { schema.validate(*typo, c); }, 1, 15,
                                               "no body named 'rinB' ('bodies' in 'testDict')");
    CHECK_THAT(text, Catch::Contains("Bodies (3): ringA, ringB, wall"));
    CHECK_THAT(text, Catch::Contains("Did you mean 'ringB'?"));
    const auto far = parse("body bar;\n");
    CHECK_THAT(requireInputError([&] { schema.validate(*far, c); }, 1, 6, "no body named 'bar'"),
               Catch::Contains("the top-level entries of system/particlesDict"));

    // Bodies not known (e.g. sphParticles): any word passes; the index cannot be asked for.
    const Params unknown = schema.validate(*far, context());
    CHECK(unknown.word("body") == "bar");
    CHECK_THROWS_AS(unknown.bodyIndex("body"), std::logic_error);
}
