// The isotropic elastic constants of IsotropicElasticity.hpp (spec §8): the conversions from
// (E, ν) against textbook values and identities, the round trip through (K, μ), and the keys
// E and nu (ν required in 2D and 3D only).
#include "materials/IsotropicElasticity.hpp"
#include "support/TestSupport.hpp"

using namespace sph;

TEST_CASE("Lamé constants, bulk and longitudinal modulus from E and nu", "[material]")
{
    // The seed's rings: E = 1 MPa, ν = 0.4 give μ = 0.3571 MPa, κ = 1.667 MPa.
    const auto rings = IsotropicElasticity::fromYoung(1.0e6, 0.4);
    CHECK(rings.E == 1.0e6);
    CHECK(rings.nu == 0.4);
    CHECK(rings.mu == Approx(1.0e6 / 2.8));
    CHECK(rings.lambda == Approx(0.4e6 / (1.4 * 0.2)));
    CHECK(rings.bulkModulus() == Approx(1.0e6 / 0.6));
    CHECK(rings.longitudinalModulus() == Approx(0.6e6 / (1.4 * 0.2)));
    // 1D is the bar in uniaxial stress: the wave modulus is E, not λ + 2μ.
    CHECK(rings.waveModulus<1>() == 1.0e6);
    CHECK(rings.waveModulus<2>() == rings.longitudinalModulus());
    CHECK(rings.waveModulus<3>() == rings.longitudinalModulus());

    // ν = 0: no lateral coupling, λ = 0, μ = E/2, M = E.
    const auto plain = IsotropicElasticity::fromYoung(2.0, 0.0);
    CHECK(plain.lambda == 0.0);
    CHECK(plain.mu == 1.0);
    CHECK(plain.longitudinalModulus() == 2.0);

    // Identities for a range of ν in (-1, 0.5).
    for (const double nu : {-0.9, -0.3, 0.0, 0.25, 0.3, 0.45, 0.499})
    {
        const double E = 3.0e4;
        const auto c = IsotropicElasticity::fromYoung(E, nu);
        CHECK(c.E == Approx(2.0 * c.mu * (1.0 + nu)));
        CHECK(c.bulkModulus() == Approx(E / (3.0 * (1.0 - 2.0 * nu))));
        CHECK(c.longitudinalModulus() == Approx(E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu))));
        // There and back through (K, μ).
        const auto back = IsotropicElasticity::fromBulkAndShear(c.bulkModulus(), c.mu);
        CHECK(back.E == Approx(E));
        CHECK(back.nu == Approx(nu).margin(1e-12));
        CHECK(back.lambda == Approx(c.lambda).margin(1e-9 * E));
        CHECK(back.mu == c.mu);
    }
}

TEST_CASE("E and nu are read with nu required in 2D and 3D only", "[material]")
{
    const auto both = test::parse("E 2e5; nu 0.25;");
    const Params p = IsotropicElasticity::schema().validate(*both, "testModel", 2);
    const auto c = IsotropicElasticity::read<3>(p);
    CHECK(c.E == 2e5);
    CHECK(c.mu == Approx(8e4));

    const auto bar = test::parse("E 3e4;");
    const Params q = IsotropicElasticity::schema().validate(*bar, "testModel", 1);
    const auto c1 = IsotropicElasticity::read<1>(q);
    CHECK(c1.E == 3e4);
    CHECK(c1.waveModulus<1>() == 3e4);
    test::requireInputError([&] { IsotropicElasticity::read<2>(q); }, 1, 3,
                            "testModel in 2D needs 'nu'");

    const auto bad = test::parse("E 3e4;\nnu 0.5;");
    test::requireInputError([&] { IsotropicElasticity::schema().validate(*bad, "testModel", 2); },
                            2, 4, "nu = 0.5 must lie in (-1, 0.5)");
}
