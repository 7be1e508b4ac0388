// Initial velocity fields built by name through the registry, the way the solver builds them
// from constant/bodies: the velocity at given points against the field's formula.
#include "core/DictionaryParser.hpp"
#include "initialConditions/fields/Fields.hpp"
#include "support/TestSupport.hpp"

#include <cmath>
#include <numbers>

using namespace sph;

namespace
{

std::unique_ptr<VelocityField<3>> twist(const std::string& text)
{
    test::loadModelLibraries();
    const auto dict = DictionaryParser::parseString("field { type twist; " + text + " }\n", "test");
    return selectModel<VelocityField<3>>(dict->find("field")->dict(), {}, 3);
}

} // namespace

TEST_CASE("twist: omega sin(pi Z / 2H) e_z x (X - axis), zero at the base", "[fields]")
{
    // The twisting column: axis through (0 0 0) along z, H = 6 m, omega = 105 rad/s.
    const auto field = twist("omega 105; point (0 0 0); height 6;");
    const double pi = std::numbers::pi;
    for (const Vec<3>& X : {Vec<3>(0.5, 0.5, 6.0), Vec<3>(0.5, -0.25, 3.0), Vec<3>(-0.125, 0.375, 0.75)})
    {
        const double w = 105.0 * std::sin(pi * X.z() / 12.0);
        const Vec<3> v = field->velocity(X);
        CHECK(v.x() == Approx(-w * X.y()).epsilon(1e-14));
        CHECK(v.y() == Approx(w * X.x()).epsilon(1e-14));
        CHECK(v.z() == 0.0);
    }
    // The top corner moves at omega r = 105 * sqrt(0.5) m/s; the base and the axis are at rest.
    CHECK(field->velocity(Vec<3>(0.5, 0.5, 6.0)).norm() == Approx(105.0 * std::sqrt(0.5)));
    CHECK(field->velocity(Vec<3>(0.5, 0.5, 0.0)).norm() == 0.0);
    CHECK(field->velocity(Vec<3>(0.0, 0.0, 4.0)).norm() == 0.0);

    // Any axis: a column along x with its base at (1 2 3) and an unnormalised axis (2 0 0)
    // gives the same field turned: s = X_x - 1, v = w(s) e_x x (X - point).
    const auto turned = twist("omega 105; point (1 2 3); axis (2 0 0); height 6;");
    const Vec<3> X(1.0 + 4.5, 2.0 + 0.3, 3.0 - 0.4);
    const double w = 105.0 * std::sin(pi * 4.5 / 12.0);
    const Vec<3> v = turned->velocity(X);
    CHECK(v.x() == 0.0);
    CHECK(v.y() == Approx(-w * -0.4).epsilon(1e-14));
    CHECK(v.z() == Approx(w * 0.3).epsilon(1e-14));
}

TEST_CASE("twist: impossible input", "[fields]")
{
    CHECK_THROWS_WITH(twist("omega 105; point (0 0 0); axis (0 0 0); height 6;"),
                      Catch::Contains("must not be the zero vector"));
    CHECK_THROWS_WITH(twist("omega 105; point (0 0 0); height 0;"), Catch::Contains("height"));
    CHECK_THROWS_WITH(twist("omega 105; point (0 0 0); height -6;"), Catch::Contains("height"));
}
