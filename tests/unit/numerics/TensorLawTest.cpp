// The logarithmic law without principal axes in 3D (docs/theory/plasticity.md §P12,
// libraries/materials/plasticity/TensorLanes.hpp):
//   - the series' strain against the principal axes of Eigen's eigen-solver, exp(2ε) back to
//     be, and the range beyond which the series is not used;
//   - the largest |principal value| of a symmetric matrix, also at double and triple eigenvalues;
//   - `logarithm series` (the default) against `logarithm principalAxes` (the law of §P4) on the
//     same random 3D points of j2Plasticity and druckerPrager, elastic and flowing, on the cone,
//     the apex and the cut-off: stresses, energies, dissipation, committed states and wave
//     speeds to round-off; a point beyond the series' range bit for bit (2D, §P13: PlaneLawTest);
//   - objectivity of the series form: F → QF rotates P and changes no scalar.
#include "numerics/PlasticPoints.hpp"

#include "materials/plasticity/TensorLanes.hpp"

#include <Eigen/Eigenvalues>

#include <numbers>

using namespace sph;

namespace
{
constexpr int N = 8;

// A rotation about a random axis.
Mat<3> randomRotation(std::mt19937& random)
{
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    const Eigen::Vector3d axis = Eigen::Vector3d(uniform(random), uniform(random), uniform(random)).normalized();
    return Eigen::AngleAxisd(std::numbers::pi * uniform(random), axis).toRotationMatrix();
}

// be = R diag(exp 2εᵢ) Rᵀ packed as SymmetricLanes' lane i; returns ε = R diag(εᵢ) Rᵀ.
Mat<3> setBe(SymmetricLanes<N>& be, int i, const Mat<3>& R, const Eigen::Vector3d& eps)
{
    const Mat<3> b = R * (2.0 * eps).array().exp().matrix().asDiagonal() * R.transpose();
    const int row[6] = {0, 1, 2, 0, 0, 1}, column[6] = {0, 1, 2, 1, 2, 2};
    for (int c = 0; c < 6; ++c)
    {
        be[c][i] = b(row[c], column[c]);
    }
    return R * eps.asDiagonal() * R.transpose();
}

void checkStrainSeries(unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (int batch = 0; batch < 20; ++batch)
    {
        SymmetricLanes<N> be;
        Mat<3> expected[N];
        for (int i = 0; i < N; ++i)
        {
            // Deviatoric strains up to 0.016 (|b̄ − 1|_F up to about 0.05), volumes ±30 %.
            const double volumetric = 0.3 * uniform(random);
            Eigen::Vector3d eps(uniform(random), uniform(random), uniform(random));
            eps *= 0.009 / std::max(eps.norm(), 1e-300) * std::abs(uniform(random));
            eps.array() += volumetric / 3.0 - eps.mean();
            if (i == 0)
            {
                eps = Eigen::Vector3d::Zero(); // exactly be = 1
            }
            if (i == 1)
            {
                eps = Eigen::Vector3d(0.004, -0.002, -0.002); // uniaxial: a double eigenvalue
            }
            expected[i] = setBe(be, i, randomRotation(random), eps);
        }
        StrainLanes<N, 6> strain;
        Lane<N> inRange;
        tensorLanes::logarithmicStrain<N>(be, strain, inRange);
        const int row[6] = {0, 1, 2, 0, 0, 1}, column[6] = {0, 1, 2, 1, 2, 2};
        for (int i = 0; i < N; ++i)
        {
            INFO("batch " << batch << ", point " << i);
            REQUIRE(inRange[i] == 1.0);
            for (int c = 0; c < 6; ++c)
            {
                CHECK(std::abs(strain.eps[c][i] - expected[i](row[c], column[c])) <= 1e-15);
            }
        }
        // exp(2ε) gives be back.
        const DeviatorLanes<N, 6> split(strain);
        SymmetricLanes<N> back;
        tensorLanes::exponentialOfTwice<N>(split, back);
        for (int c = 0; c < 6; ++c)
        {
            for (int i = 0; i < N; ++i)
            {
                CHECK(std::abs(back[c][i] - be[c][i]) <= 8e-16 * std::max(be[0][i], 1.0));
            }
        }
    }
}

} // namespace

TEST_CASE("tensor law: the series' strain is ½ ln be of the principal axes, and exp(2ε) is be",
          "[tensorLaw]")
{
    checkStrainSeries(11);
    checkStrainSeries(12);
}

TEST_CASE("tensor law: beyond the series' range a point is marked for the principal axes",
          "[tensorLaw]")
{
    std::mt19937 random(13);
    SymmetricLanes<N> be;
    for (int i = 0; i < N; ++i)
    {
        // |b̄ − 1|_F ≈ 2 |dev ε| √… : a deviatoric strain of norm 0.02 is inside, 0.03 outside.
        const double size = i < 4 ? 0.02 : 0.03;
        const Eigen::Vector3d eps = size / std::sqrt(1.5) * Eigen::Vector3d(1.0, -0.5, -0.5);
        setBe(be, i, randomRotation(random), eps);
    }
    be[0][7] = -1.0; // not positive definite
    StrainLanes<N, 6> strain;
    Lane<N> inRange;
    tensorLanes::logarithmicStrain<N>(be, strain, inRange);
    for (int i = 0; i < N; ++i)
    {
        INFO("point " << i);
        CHECK(inRange[i] == (i < 4 ? 1.0 : 0.0));
    }
}

TEST_CASE("tensor law: the largest |principal value|, also at double and triple eigenvalues",
          "[tensorLaw]")
{
    std::mt19937 random(14);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    double worst = 0.0;
    for (int batch = 0; batch < 20; ++batch)
    {
        SymmetricLanes<N> a;
        double expected[N];
        for (int i = 0; i < N; ++i)
        {
            Eigen::Vector3d values(uniform(random), uniform(random), uniform(random));
            values *= 1e9;
            if (i == 1)
            {
                values = Eigen::Vector3d(-3e8, -3e8, 5e8); // double
            }
            if (i == 2)
            {
                values = Eigen::Vector3d(-7e8, 2e8, 2e8 * (1.0 + 1e-12)); // nearly double
            }
            if (i == 3)
            {
                values = Eigen::Vector3d::Constant(-4e8); // triple
            }
            if (i == 4)
            {
                values = Eigen::Vector3d::Zero();
            }
            if (i == 5)
            {
                values = Eigen::Vector3d(6e8, -6e8, 0.0); // pure shear: the farthest start
            }
            const Mat<3> R = randomRotation(random);
            const Mat<3> A = R * values.asDiagonal() * R.transpose();
            const int row[6] = {0, 1, 2, 0, 0, 1}, column[6] = {0, 1, 2, 1, 2, 2};
            for (int c = 0; c < 6; ++c)
            {
                a[c][i] = A(row[c], column[c]);
            }
            expected[i] = values.cwiseAbs().maxCoeff();
        }
        const Lane<N> largest = tensorLanes::largestAbsoluteEigenvalue<N>(a);
        for (int i = 0; i < N; ++i)
        {
            INFO("batch " << batch << ", point " << i);
            CHECK(std::abs(largest[i] - expected[i]) <= 1e-14 * 1e9);
            worst = std::max(worst, std::abs(largest[i] - expected[i]));
        }
    }
    INFO("largest error " << worst);
    CHECK(worst > 0.0); // the check is not vacuous
}

namespace
{
using test::Body;
using test::compareTheForms;
using test::RandomPoints;
using test::sameBits;
using namespace test::plasticMaterials;
} // namespace

TEST_CASE("tensor law: druckerPrager in series form is its principal-axes law to round-off",
          "[tensorLaw][plasticity]")
{
    CHECK(compareTheForms<3>(sand, 1.01 * Mat<3>::Identity(), 0.003, 8, 3) > 4);  // open voids
    CHECK(compareTheForms<3>(sand, 0.997 * Mat<3>::Identity(), 0.008, 17, 4) > 4); // compressed
    const std::size_t cone = compareTheForms<3>(dp, Mat<3>::Identity(), 0.0015, 21, 9);
    CHECK(cone > 3);
    CHECK(cone < 18);
    CHECK(compareTheForms<3>(dp, 1.02 * Mat<3>::Identity(), 0.003, 11, 10) > 8);
    const std::string associative = "type druckerPrager; E 7.2e6; nu 0.2; rho 2000; "
                                    "frictionAngle 30; dilatancyAngle 30; cohesion 1e4;";
    CHECK(compareTheForms<3>(associative, Mat<3>::Identity(), 0.003, 16, 15) > 3);
}

TEST_CASE("tensor law: j2Plasticity in series form is its principal-axes law to round-off",
          "[tensorLaw][plasticity]")
{
    const std::size_t flowing3 = compareTheForms<3>(copper, 0.97 * Mat<3>::Identity(), 0.003, 27, 6);
    CHECK(flowing3 > 3);
    CHECK(flowing3 < 24);
    // Virgin points stretched along a random axis: be has a double eigenvalue.
    CHECK(compareTheForms<3>(copper, Mat<3>::Identity(), 0.004, 16, 7, true) > 3);
}

TEST_CASE("tensor law: a point beyond the series' range takes the principal axes, bit for bit",
          "[tensorLaw][plasticity]")
{
    // Elastic shear of 4 % (no yielding below 1e12 Pa): outside the series' range.
    const std::string stiff = "type j2Plasticity; E 1e6; nu 0.3; rho 1000; yieldStress 1e12;";
    Mat<3> F = Mat<3>::Identity();
    F(0, 1) = 0.08;
    test::MaterialPoint<3> series(stiff);
    test::MaterialPoint<3> axes(stiff + " logarithm principalAxes;");
    CHECK(sameBits(series.stress(F), axes.stress(F)));
    CHECK(sameBits(series.energy(F), axes.energy(F)));
    // ... and inside it the two differ (so the check above is not vacuous).
    F(0, 1) = 0.01;
    CHECK(!sameBits(series.stress(F), axes.stress(F)));
}

TEST_CASE("tensor law: a rotation of a yielded point rotates its stress and changes no scalar",
          "[tensorLaw][plasticity]")
{
    std::mt19937 random(21);
    const RandomPoints<3> points(0.98 * Mat<3>::Identity(), 0.006, 16, 22, false);
    Body<3> body(copper, points);
    constexpr std::size_t stride = PlasticState<3>::packedSize;
    std::vector<Mat<3>> P(16), PRotated(16), rotatedF(16);
    std::vector<double> psi(16), psiRotated(16), next(16 * stride), nextRotated(16 * stride),
        dissipation(16), dissipationRotated(16);
    const Mat<3> Q = randomRotation(random);
    for (std::size_t i = 0; i < 16; ++i)
    {
        rotatedF[i] = Q * points.F[i];
    }
    body.material->evaluate(points.F.data(), P.data(), psi.data(), 16,
                            HistoryOf::samples(points.states.data(), stride, next.data(), dissipation.data()));
    body.material->evaluate(rotatedF.data(), PRotated.data(), psiRotated.data(), 16,
                            HistoryOf::samples(points.states.data(), stride, nextRotated.data(),
                                               dissipationRotated.data()));
    std::size_t flowing = 0;
    for (std::size_t i = 0; i < 16; ++i)
    {
        INFO("point " << i);
        CHECK((PRotated[i] - Q * P[i]).norm() <= 1e-13 * P[i].norm());
        CHECK(std::abs(psiRotated[i] - psi[i]) <= 1e-13 * psi[i]);
        CHECK(std::abs(dissipationRotated[i] - dissipation[i]) <= 1e-12 * dissipation[i] + 1e-3);
        // Cp⁻¹ is a material tensor: unchanged by the rotation.
        for (std::size_t k = 0; k < stride; ++k)
        {
            CHECK(std::abs(nextRotated[i * stride + k] - next[i * stride + k]) <=
                  1e-13 * (std::abs(next[i * stride + k]) + 1.0));
        }
        flowing += dissipation[i] > 0.0 ? 1 : 0;
    }
    CHECK(flowing > 3);
}
