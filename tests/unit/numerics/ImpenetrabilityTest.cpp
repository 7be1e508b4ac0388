// The close-pair energy of docs/theory/impenetrability.md, in 1D/2D/3D:
//   - zero energy and force where no pair is closer than δ spacings (§I2: the continuum is
//     left alone, bit for bit);
//   - force = −∂Π_I/∂x by central differences where pairs overlap (I3.1);
//   - linear and angular momentum of the forces zero to round-off; a rigid rotation rotates
//     the forces and keeps the energy (§I3);
//   - a pair driven together stores ½ M V̄ δ² (§I2, the barrier), M = ρ0 c0².
#include "numerics/NumericsSupport.hpp"
#include "stabilisation/Impenetrability.hpp"

using namespace sph;

namespace
{

const char* kMaterial = "type neoHookean; mu 1; kappa 5; rho 2;";

template <int D>
struct PairFixture
{
    test::SchemeFixture<D> fixture;
    Impenetrability<D> guard;

    explicit PairFixture(double distance, double perturbation = 0.2)
        : fixture(test::lattice<D>(D == 3 ? 4 : (D == 2 ? 7 : 12), perturbation, 3),
                  "type none;", kMaterial, false, test::schemeHOverDx<D>()),
          guard(distance, fixture.materials)
    {
    }
    double energy(const std::vector<Vec<D>>& x) const
    {
        return guard.energy(x, fixture.V0, fixture.body, fixture.ref, nullptr);
    }
    std::vector<Vec<D>> forces(const std::vector<Vec<D>>& x, double* energy = nullptr) const
    {
        std::vector<Vec<D>> T(x.size(), Vec<D>::Zero());
        const double e = guard.addForces(x, fixture.V0, fixture.body, fixture.ref, nullptr, T,
                                         energy != nullptr);
        if (energy)
        {
            *energy = e;
        }
        return T;
    }
};

// Positions with some pairs pushed to within a fraction of a spacing of each other.
template <int D>
std::vector<Vec<D>> squeezed(const std::vector<Vec<D>>& x0)
{
    std::vector<Vec<D>> x = x0;
    for (std::size_t a = 0; a + 1 < x.size(); a += 3)
    {
        x[a + 1] = x[a] + 0.15 * (x[a + 1] - x[a]).normalized() * (1.0 + 0.1 * double(a % 4));
    }
    return x;
}

template <int D>
Mat<D> rotation()
{
    Mat<D> R = Mat<D>::Identity();
    if constexpr (D >= 2)
    {
        const double t = 0.7;
        R(0, 0) = std::cos(t);
        R(0, 1) = -std::sin(t);
        R(1, 0) = std::sin(t);
        R(1, 1) = std::cos(t);
    }
    if constexpr (D == 3)
    {
        Mat<D> S = Mat<D>::Identity();
        const double t = -0.4;
        S(1, 1) = std::cos(t);
        S(1, 2) = -std::sin(t);
        S(2, 1) = std::sin(t);
        S(2, 2) = std::cos(t);
        R = S * R;
    }
    return R;
}

template <int D>
void checkImpenetrability()
{
    CAPTURE(D);
    SECTION("no pair closer than the distance: no energy, no force")
    {
        // The lattice (perturbation 0.2: pairs at least 0.6 apart) compressed uniformly to
        // 0.9: the closest pairs are at 0.54 > 0.5.
        PairFixture<D> p(0.5);
        std::vector<Vec<D>> x = p.fixture.X;
        for (auto& point : x)
        {
            point *= 0.9;
        }
        double e = -1.0;
        const auto T = p.forces(x, &e);
        CHECK(e == 0.0);
        for (const auto& t : T)
        {
            CHECK(t.norm() == 0.0);
        }
    }
    SECTION("force = -dPi/dx, momentum, objectivity")
    {
        PairFixture<D> p(0.5);
        const auto x = squeezed(p.fixture.X);
        double e = 0.0;
        const auto T = p.forces(x, &e);
        REQUIRE(e > 0.0);
        REQUIRE(e == Approx(p.energy(x)).epsilon(1e-14));
        const double scale = test::largestComponent(T);
        REQUIRE(scale > 0.0);
        const double fdError = test::largestGradientError<D>(
            [&](const std::vector<Vec<D>>& y) { return p.energy(y); }, x, T);
        CHECK(fdError < 1e-7 * scale);

        Vec<D> momentum = Vec<D>::Zero();
        double angular = 0.0;
        for (std::size_t a = 0; a < x.size(); ++a)
        {
            momentum += T[a];
            if constexpr (D >= 2)
            {
                angular += x[a][0] * T[a][1] - x[a][1] * T[a][0];
            }
        }
        CHECK(momentum.norm() < 1e-13 * scale * double(x.size()));
        CHECK(std::abs(angular) < 1e-12 * scale * double(x.size()) * double(x.size()));

        const Mat<D> R = rotation<D>();
        std::vector<Vec<D>> xRotated = x;
        for (auto& point : xRotated)
        {
            point = R * point + Vec<D>::Constant(0.3);
        }
        double eRotated = 0.0;
        const auto TRotated = p.forces(xRotated, &eRotated);
        CHECK(eRotated == Approx(e).epsilon(1e-12));
        for (std::size_t a = 0; a < x.size(); ++a)
        {
            CHECK((TRotated[a] - R * T[a]).norm() < 1e-12 * scale);
        }
    }
    SECTION("a pair driven together stores half M Vbar delta squared")
    {
        const double delta = 0.5;
        PairFixture<D> p(delta, 0.0); // a regular lattice: spacing 1, volume 1
        const double c0 = p.fixture.material->waveSpeed(Mat<D>::Identity());
        const double M = p.fixture.material->density() * c0 * c0;
        std::vector<Vec<D>> x = p.fixture.X;
        x[1] = x[0]; // particles 0 and 1 are lattice neighbours along e_0
        CHECK(p.energy(x) == Approx(0.5 * M * 1.0 * delta * delta).epsilon(1e-14));
        x[1] = x[0] + Vec<D>::Unit(0) * 0.2;
        CHECK(p.energy(x) == Approx(0.5 * M * 0.3 * 0.3).epsilon(1e-14));
        // Less than the distance apart along the same line, the force pushes them apart.
        const auto T = p.forces(x);
        CHECK(T[1][0] == Approx(M * 0.3).epsilon(1e-14));
        CHECK(T[0][0] == Approx(-M * 0.3).epsilon(1e-14));
    }
}

} // namespace

TEST_CASE("impenetrability: energy, force, momentum, objectivity (1D)", "[impenetrability]")
{
    checkImpenetrability<1>();
}

TEST_CASE("impenetrability: energy, force, momentum, objectivity (2D)", "[impenetrability]")
{
    checkImpenetrability<2>();
}

TEST_CASE("impenetrability: energy, force, momentum, objectivity (3D)", "[impenetrability]")
{
    checkImpenetrability<3>();
}
