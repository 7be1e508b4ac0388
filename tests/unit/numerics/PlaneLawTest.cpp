// The plane-strain logarithmic law in closed form without axes (docs/theory/plasticity.md §P13,
// libraries/materials/plasticity/PlaneLanes.hpp, LaneFunctions.hpp):
//   - ln y and exp y against the C library, on the series' branch and beyond it;
//   - the strain ε = ½ ln be against Eigen's eigen-solver, in the series' range and beyond it
//     (where the C library's log and atanh take over), at a double eigenvalue (be a dilation)
//     and at be = 1 exactly; exp(2ε) back to be;
//   - the largest |principal value| of a plane-strain stress;
//   - `logarithm series` (the default) against `logarithm principalAxes` (the law of §P4) on
//     random 2D points of j2Plasticity and druckerPrager, elastic and flowing, on the cone, the
//     apex and the cut-off, and elastic strains beyond the series' range: stresses, energies,
//     dissipation, committed states and wave speeds to round-off;
//   - objectivity: F → QF rotates P and changes no scalar.
#include "numerics/PlasticPoints.hpp"

#include "materials/plasticity/PlaneLanes.hpp"

#include <Eigen/Eigenvalues>

#include <limits>
#include <numbers>

using namespace sph;

namespace
{
constexpr int N = 8;

Mat<2> rotation(double angle)
{
    Mat<2> R;
    R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    return R;
}

// Lane i of a plane-strain be with principal strains eps (in-plane ε₀, ε₁ along R's columns,
// then zz); returns the in-plane ε = R diag(ε₀, ε₁) Rᵀ.
Mat<2> setBe(Lane<N> (&be)[2][2], Lane<N>& beZZ, int i, const Mat<2>& R, const Eigen::Vector3d& eps)
{
    const Eigen::Vector2d stretch(std::exp(2.0 * eps[0]), std::exp(2.0 * eps[1]));
    const Mat<2> b = R * stretch.asDiagonal() * R.transpose();
    for (int k = 0; k < 2; ++k)
    {
        for (int l = 0; l < 2; ++l)
        {
            be[k][l][i] = b(k, l);
        }
    }
    beZZ[i] = std::exp(2.0 * eps[2]);
    return R * eps.head<2>().asDiagonal() * R.transpose();
}

} // namespace

TEST_CASE("plane law: ln y by the series and by the C library", "[tensorLaw]")
{
    // y from 0.5 to 2: both branches (the series for y in [3/4, 4/3]).
    int seriesPoints = 0;
    for (int j = 0; j < 64; ++j)
    {
        Lane<N> y;
        for (int i = 0; i < N; ++i)
        {
            y[i] = 0.5 * std::pow(4.0, (j * N + i) / (64.0 * N - 1.0));
        }
        const Lane<N> value = laneFunctions::logarithm<N>(y);
        for (int i = 0; i < N; ++i)
        {
            INFO("y = " << y[i]);
            const double exact = std::log(y[i]);
            CHECK(std::abs(value[i] - exact) <= 5e-16 * std::abs(exact)); // 2 ulp (t's two roundings)
            seriesPoints += y[i] >= 0.75 && y[i] <= 4.0 / 3.0 ? 1 : 0;
        }
    }
    CHECK(seriesPoints > 100);
    CHECK(laneFunctions::logarithm<N>(Lane<N>::Ones()).isZero(0.0)); // ln 1 = 0 exactly
    // Not positive: the C library's −inf and NaN, as the principal form gave.
    Lane<N> bad = Lane<N>::Ones();
    bad[1] = 0.0;
    bad[2] = -1.0;
    const Lane<N> logs = laneFunctions::logarithm<N>(bad);
    CHECK(std::isinf(logs[1]));
    CHECK(std::isnan(logs[2]));
}

TEST_CASE("lane functions: exp y by the series and by the C library", "[tensorLaw]")
{
    // y from −0.5 to 0.5: both branches (the series for |y| ≤ 1/8).
    int seriesPoints = 0;
    for (int j = 0; j < 64; ++j)
    {
        Lane<N> y;
        for (int i = 0; i < N; ++i)
        {
            y[i] = -0.5 + (j * N + i) / (64.0 * N - 1.0);
        }
        const Lane<N> value = laneFunctions::exponential<N>(y);
        for (int i = 0; i < N; ++i)
        {
            INFO("y = " << y[i]);
            CHECK(std::abs(value[i] - std::exp(y[i])) <= 3e-16 * std::exp(y[i])); // ~1 ulp
            seriesPoints += std::abs(y[i]) <= laneFunctions::expRange ? 1 : 0;
        }
    }
    CHECK(seriesPoints > 100);
    CHECK(laneFunctions::exponential<N>(Lane<N>::Zero()).isOnes(0.0)); // exp 0 = 1 exactly
    Lane<N> nan = Lane<N>::Zero();
    nan[3] = std::numeric_limits<double>::quiet_NaN();
    CHECK(std::isnan(laneFunctions::exponential<N>(nan)[3]));
}

TEST_CASE("plane law: the strain is ½ ln be of the principal axes, and exp(2ε) is be", "[tensorLaw]")
{
    std::mt19937 random(31);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    int hyperbolicSeries = 0, hyperbolicLibrary = 0; // exp(2ε)'s two branches (P13.4)
    for (int batch = 0; batch < 40; ++batch)
    {
        Lane<N> be[2][2], beZZ;
        Mat<2> expected[N];
        double expectedZZ[N];
        for (int i = 0; i < N; ++i)
        {
            // In-plane shears up to 0.2 (the series to atanh x ≤ 0.144, the C library beyond),
            // volumes ±0.4 (the logarithm's series to about ±0.14, the C library beyond).
            Eigen::Vector3d eps(uniform(random), uniform(random), uniform(random));
            eps *= batch % 2 == 0 ? 0.02 : 0.2;
            if (i == 0)
            {
                eps.setZero(); // be = 1 exactly
            }
            if (i == 1)
            {
                eps = Eigen::Vector3d(0.03, 0.03, -0.01); // a dilation in-plane: r = 0
            }
            expected[i] = setBe(be, beZZ, i, rotation(std::numbers::pi * uniform(random)), eps);
            expectedZZ[i] = eps[2];
            if (i == 0)
            {
                be[0][0][i] = be[1][1][i] = beZZ[i] = 1.0;
                be[0][1][i] = be[1][0][i] = 0.0;
            }
        }
        StrainLanes<N, 4> strain;
        planeLanes::logarithmicStrain<N>(be, beZZ, strain);
        for (int i = 0; i < N; ++i)
        {
            INFO("batch " << batch << ", point " << i);
            const double tolerance = 1e-15 * std::max(1.0, 10.0 * expected[i].norm());
            CHECK(std::abs(strain.eps[0][i] - expected[i](0, 0)) <= tolerance);
            CHECK(std::abs(strain.eps[1][i] - expected[i](1, 1)) <= tolerance);
            CHECK(std::abs(strain.eps[3][i] - expected[i](0, 1)) <= tolerance);
            CHECK(std::abs(strain.eps[2][i] - expectedZZ[i]) <= tolerance);
            if (i == 0)
            {
                for (int c = 0; c < 4; ++c)
                {
                    CHECK(strain.eps[c][i] == 0.0);
                }
            }
        }
        // exp(2ε) gives be back.
        const DeviatorLanes<N, 4> split(strain);
        Lane<N> B[2][2], zz;
        planeLanes::exponentialOfTwice<N>(split, B, zz);
        for (int i = 0; i < N; ++i)
        {
            INFO("batch " << batch << ", point " << i);
            for (int k = 0; k < 2; ++k)
            {
                for (int l = 0; l < 2; ++l)
                {
                    CHECK(std::abs(B[k][l][i] - be[k][l][i]) <= 2e-15 * std::max(be[0][0][i], 1.0));
                }
            }
            CHECK(std::abs(zz[i] - beZZ[i]) <= 2e-15 * beZZ[i]);
            const double d = 0.5 * (split.dev[0][i] - split.dev[1][i]);
            const double x2 = 4.0 * (d * d + split.dev[3][i] * split.dev[3][i]);
            (x2 <= planeLanes::hyperbolicRange ? hyperbolicSeries : hyperbolicLibrary) += 1;
        }
    }
    CHECK(hyperbolicSeries > 100);
    CHECK(hyperbolicLibrary > 10);
}

TEST_CASE("plane law: the largest |principal value| of a plane-strain stress", "[tensorLaw]")
{
    std::mt19937 random(33);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Lane<N> tau[4];
    double expected[N];
    for (int i = 0; i < N; ++i)
    {
        Eigen::Vector3d values(uniform(random), uniform(random), uniform(random));
        values *= 1e8;
        if (i == 0)
        {
            values = Eigen::Vector3d(3e8, -3e8, 1e8); // pure shear in-plane
        }
        if (i == 1)
        {
            values = Eigen::Vector3d(1e8, 1e8, -4e8); // zz the largest, in-plane double
        }
        const Mat<2> R = rotation(std::numbers::pi * uniform(random));
        const Mat<2> A = R * values.head<2>().asDiagonal() * R.transpose();
        tau[0][i] = A(0, 0);
        tau[1][i] = A(1, 1);
        tau[2][i] = values[2];
        tau[3][i] = A(0, 1);
        expected[i] = values.cwiseAbs().maxCoeff();
    }
    const Lane<N> largest = planeLanes::largestAbsolutePrincipal<N>(tau);
    for (int i = 0; i < N; ++i)
    {
        INFO("point " << i);
        CHECK(std::abs(largest[i] - expected[i]) <= 1e-15 * 4e8);
    }
}

namespace
{
using test::compareTheForms;
using namespace test::plasticMaterials;
} // namespace

TEST_CASE("plane law: druckerPrager in closed form is its principal-axes law to round-off",
          "[tensorLaw][plasticity]")
{
    CHECK(compareTheForms<2>(sand, 1.01 * Mat<2>::Identity(), 0.003, 16, 3) > 4);   // open voids
    CHECK(compareTheForms<2>(sand, 0.997 * Mat<2>::Identity(), 0.008, 17, 4) > 4); // compressed
    const std::size_t cone = compareTheForms<2>(dp, Mat<2>::Identity(), 0.0015, 21, 9);
    CHECK(cone > 3);
    CHECK(cone < 18);
    CHECK(compareTheForms<2>(dp, 1.02 * Mat<2>::Identity(), 0.003, 11, 10) > 6);
    const std::string associative = "type druckerPrager; E 7.2e6; nu 0.2; rho 2000; "
                                    "frictionAngle 30; dilatancyAngle 30; cohesion 1e4;";
    CHECK(compareTheForms<2>(associative, Mat<2>::Identity(), 0.003, 16, 15) > 3);
}

TEST_CASE("plane law: j2Plasticity in closed form is its principal-axes law to round-off",
          "[tensorLaw][plasticity]")
{
    const std::size_t flowing = compareTheForms<2>(copper, 0.995 * Mat<2>::Identity(), 0.003, 27, 6);
    CHECK(flowing > 3);
    CHECK(flowing < 24);
    CHECK(compareTheForms<2>(copper, Mat<2>::Identity(), 0.004, 16, 7, true) > 3); // uniaxial
    // The rings' rubber of the benchmark: elastic strains of a few per cent, yielding.
    const std::string rubber = "type j2Plasticity; E 1e6; nu 0.4; rho 1000; yieldStress 2e4; "
                               "hardeningModulus 1e5;";
    CHECK(compareTheForms<2>(rubber, Mat<2>::Identity(), 0.05, 24, 8) > 3);
    // Elastic strains beyond both series' ranges (the C library's branches): shear and volume
    // of 20-30 %.
    const std::string stiff = "type j2Plasticity; E 1e6; nu 0.3; rho 1000; yieldStress 1e12;";
    CHECK(compareTheForms<2>(stiff, 0.8 * Mat<2>::Identity(), 0.3, 24, 12) == 0);
}

TEST_CASE("plane law: the closed form is used in 2D, and principalAxes keeps §P4",
          "[tensorLaw][plasticity]")
{
    Mat<2> F = Mat<2>::Identity();
    F(0, 1) = 0.01;
    test::MaterialPoint<2> series(copper);
    test::MaterialPoint<2> axes(copper + " logarithm principalAxes;");
    // The two forms compute in another order: not the same bits (so the comparisons above
    // compare two different computations).
    CHECK(!test::sameBits(series.stress(F), axes.stress(F)));
    CHECK((series.stress(F) - axes.stress(F)).norm() <= 1e-12 * axes.stress(F).norm());
}

TEST_CASE("plane law: a rotation of a yielded point rotates its stress and changes no scalar",
          "[tensorLaw][plasticity]")
{
    constexpr std::size_t count = 16;
    constexpr std::size_t stride = PlasticState<2>::packedSize;
    const test::RandomPoints<2> points(0.98 * Mat<2>::Identity(), 0.006, count, 22, false);
    test::Body<2> body(copper, points);
    std::vector<Mat<2>> P(count), PRotated(count), rotatedF(count);
    std::vector<double> psi(count), psiRotated(count), next(count * stride),
        nextRotated(count * stride), dissipation(count), dissipationRotated(count);
    const Mat<2> Q = rotation(0.7);
    for (std::size_t i = 0; i < count; ++i)
    {
        rotatedF[i] = Q * points.F[i];
    }
    body.material->evaluate(points.F.data(), P.data(), psi.data(), count,
                            HistoryOf::samples(points.states.data(), stride, next.data(),
                                               dissipation.data()));
    body.material->evaluate(rotatedF.data(), PRotated.data(), psiRotated.data(), count,
                            HistoryOf::samples(points.states.data(), stride, nextRotated.data(),
                                               dissipationRotated.data()));
    std::size_t flowing = 0;
    for (std::size_t i = 0; i < count; ++i)
    {
        INFO("point " << i);
        CHECK((PRotated[i] - Q * P[i]).norm() <= 1e-13 * P[i].norm());
        CHECK(std::abs(psiRotated[i] - psi[i]) <= 1e-13 * psi[i]);
        CHECK(std::abs(dissipationRotated[i] - dissipation[i]) <= 1e-12 * dissipation[i] + 1e-3);
        for (std::size_t k = 0; k < stride; ++k) // Cp⁻¹ is a material tensor
        {
            CHECK(std::abs(nextRotated[i * stride + k] - next[i * stride + k]) <=
                  1e-13 * (std::abs(next[i * stride + k]) + 1.0));
        }
        flowing += dissipation[i] > 0.0 ? 1 : 0;
    }
    CHECK(flowing > 3);
}
