// Particle generators (sphParticles): counts, volumes, spacing, symmetry, file round trip.
#include "initialConditions/generators/Generator.hpp"
#include "io/VtuFile.hpp"
#include "solver/ParticleFile.hpp"
#include "support/CaseRunner.hpp"

#include "core/DictionaryParser.hpp"

#include <numbers>

using namespace sph;

namespace
{

InitialParticles generateText(const std::string& text, int dimension,
                              const std::filesystem::path& caseDir = ".")
{
    test::loadModelLibraries();
    const auto dict = DictionaryParser::parseString(text, "system/particlesDict");
    return generateParticles(*dict, dimension, caseDir);
}

double totalVolume(const InitialParticles& p)
{
    double sum = 0.0;
    for (double v : p.V)
    {
        sum += v;
    }
    return sum;
}

} // namespace

TEST_CASE("line: both ends included, half end volumes tile the bar", "[generator]")
{
    const auto half = generateText("bar { type line; start 0; end 0.1333; n 40; }", 1);
    REQUIRE(half.size() == 40);
    CHECK(half.spacing == Approx(0.1333 / 39));
    CHECK(half.X[0] == 0.0);
    CHECK(half.X[3 * 39] == 0.1333);
    CHECK(half.V[0] == Approx(0.5 * half.spacing));
    CHECK(totalVolume(half) == Approx(0.1333).epsilon(1e-14));
    const auto full = generateText("bar { type line; start 0; end 1; n 11; endVolumes full; }", 1);
    CHECK(totalVolume(full) == Approx(1.1));
}

TEST_CASE("box: cell-centred lattice tiles the box", "[generator]")
{
    const auto box = generateText("b { type box; min (0 0); max (0.02 0.01); spacing 1e-3; }", 2);
    CHECK(box.size() == 200);
    CHECK(totalVolume(box) == Approx(2e-4));
    CHECK(box.X[0] == Approx(0.5e-3));
    const auto cube = generateText("b { type box; min (0 0 0); max (1 2 3); spacing 0.5; }", 3);
    CHECK(cube.size() == 2 * 4 * 6);
    CHECK_THROWS_WITH(
        generateText("b { type box; min (0 0); max (0.0105 0.01); spacing 1e-3; }", 2),
        Catch::Contains("not a whole number of spacings"));
}

TEST_CASE("polygon: a rectangle is box's lattice, a slope's particles, half-open edges, bad "
          "polygons refused",
          "[generator]")
{
    // A rectangle, either way round: exactly box's particles.
    const auto box = generateText("b { type box; min (0 0); max (0.02 0.01); spacing 1e-3; }", 2);
    for (const char* text :
         {"b { type polygon; vertices ((0 0) (0.02 0) (0.02 0.01) (0 0.01)); spacing 1e-3; }",
          "b { type polygon; vertices ((0 0.01) (0.02 0.01) (0.02 0) (0 0)); spacing 1e-3; }"})
    {
        const auto rectangle = generateText(text, 2);
        REQUIRE(rectangle.size() == box.size());
        CHECK(rectangle.X == box.X);
        CHECK(rectangle.V == box.V);
    }
    // A 2:1 slope of height 1 on a base from x = 0 to 4 (crest 0 to 2, toe at 4), spacing
    // 0.25: 4 rows of 16, 14, 12, 10 cells whose centres lie under the face x + 2y <= 4 (the
    // rows at y = 0.125, 0.375, 0.625, 0.875 keep x < 3.75, 3.25, 2.75, 2.25: 15, 13, 11, 9
    // centres) and the crest's 8 per row: 48 particles, area 3 against 48/16 = 3.
    const auto slope =
        generateText("s { type polygon; vertices ((0 0) (4 0) (2 1) (0 1)); spacing 0.25; }", 2);
    CHECK(slope.size() == 48);
    CHECK(totalVolume(slope) == Approx(3.0));
    for (std::size_t a = 0; a < slope.size(); ++a)
    {
        CHECK(slope.X[3 * a] + 2.0 * slope.X[3 * a + 1] < 4.0);
    }
    // Two triangles sharing a diagonal that runs through lattice centres: every centre of the
    // square goes to exactly one of them.
    const auto lower =
        generateText("t { type polygon; vertices ((0 0) (1 0) (1 1)); spacing 0.1; }", 2);
    const auto upper =
        generateText("t { type polygon; vertices ((0 0) (1 1) (0 1)); spacing 0.1; }", 2);
    CHECK(lower.size() + upper.size() == 100);
    // Bad polygons, each at its key with the reason.
    CHECK_THROWS_WITH(generateText("p { type polygon; vertices ((0 0) (1 0)); spacing 0.1; }", 2),
                      Catch::Contains("2 vertices do not enclose an area"));
    CHECK_THROWS_WITH(
        generateText("p { type polygon; vertices ((0 0) (1 1) (1 0) (0 1)); spacing 0.1; }", 2),
        Catch::Contains("not a simple polygon"));
    CHECK_THROWS_WITH(
        generateText("p { type polygon; vertices ((0 0) (1 0) (1 0) (0 1)); spacing 0.1; }", 2),
        Catch::Contains("corners 2 and 3 are the same point"));
    CHECK_THROWS_WITH(
        generateText("p { type polygon; vertices ((0 0) (1 0) (2 0)); spacing 0.1; }", 2),
        Catch::Contains("collinear"));
    CHECK_THROWS_WITH(
        generateText("p { type polygon; vertices ((0 0) (1 0) (0 0.01)); spacing 0.1; }", 2),
        Catch::Contains("no particle centre falls inside"));
    CHECK_THROWS_WITH(
        generateText("p { type polygon; vertices ((0 0 0) (1 0 0) (0 1 0)); spacing 0.1; }", 3),
        Catch::Contains("polygon"));
}

TEST_CASE("annulus and disk: clipped square lattice, mirror symmetric", "[generator]")
{
    const auto rings = generateText("ringA { type annulus; centre (-0.045 0); innerRadius 0.03; "
                                    "outerRadius 0.04; spacing 1e-3; }\n"
                                    "ringB { type annulus; centre (0.045 0); innerRadius 0.03; "
                                    "outerRadius 0.04; spacing 1e-3; }\n",
                                    2);
    const std::size_t perRing = rings.size() / 2;
    REQUIRE(rings.size() == 2 * perRing);
    // About π(R² - r²)/Δx² particles.
    CHECK(static_cast<double>(perRing) ==
          Approx(std::numbers::pi * (0.04 * 0.04 - 0.03 * 0.03) / 1e-6).epsilon(0.01));
    // Ring B is the mirror image of ring A.
    std::multiset<std::pair<long, long>> a;
    std::multiset<std::pair<long, long>> b;
    for (std::size_t i = 0; i < rings.size(); ++i)
    {
        const long x = std::lround(rings.X[3 * i] * 1e6);
        const long y = std::lround(rings.X[3 * i + 1] * 1e6);
        (rings.body[i] == 0 ? a : b)
            .insert(rings.body[i] == 0 ? std::make_pair(-x, y) : std::make_pair(x, y));
    }
    CHECK(a == b);
    const auto disk = generateText("d { type disk; centre (0 0); radius 0.01; spacing 1e-3; }", 2);
    CHECK(static_cast<double>(disk.size()) == Approx(std::numbers::pi * 100).epsilon(0.03));
}

TEST_CASE("cylinder (3D) and dimension checks", "[generator]")
{
    const auto c = generateText(
        "c { type cylinder; base (0 0 0); axis (0 0 1); length 0.01; radius 0.005; spacing 1e-3; }",
        3);
    CHECK(static_cast<double>(c.size()) == Approx(11 * std::numbers::pi * 25).epsilon(0.05));
    CHECK_THROWS_WITH(
        generateText("c { type annulus; centre (0); innerRadius 1; outerRadius 2; spacing 0.1; }",
                     1),
        Catch::Contains("generator type 'annulus' is not available in 1D"));
    CHECK_THROWS_WITH(generateText("a { type box; min (0 0); max (1 1); spacing 0.5; }\n"
                                   "b { type box; min (2 0); max (3 1); spacing 0.25; }",
                                   2),
                      Catch::Contains("give every body the same spacing"));
}

TEST_CASE("particle file and vtu import round trip", "[generator]")
{
    test::TempDir dir;
    const auto box = generateText("b { type box; min (0 0); max (0.004 0.003); spacing 1e-3; }", 2);
    writeParticleFile(dir.path() / "constant" / "particles.vtu", box);
    const InitialParticles back = readParticleFile(dir.path() / "constant" / "particles.vtu");
    CHECK(back.X == box.X);
    CHECK(back.V == box.V);
    CHECK(back.body == box.body);
    CHECK(back.bodyNames == box.bodyNames);
    CHECK(back.spacing == box.spacing);
    CHECK(back.dimension == 2);
    const auto imported = generateText(
        "b { type vtu; file \"constant/particles.vtu\"; spacing 1e-3; volumeArray volume; }", 2,
        dir.path());
    CHECK(imported.X == box.X);
    CHECK(imported.V == box.V);
}
