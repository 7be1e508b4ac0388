#pragma once
// Motions and checks shared by the tests of gradF's samples in plastic flow
// (GradFPlasticTest, GradFParticleVolumeTest).

#include "numerics/NumericsSupport.hpp"

namespace sph::test
{

// The materials of these tests, in units where the cloud's spacing is 1: yielding from a strain
// of 0.8 % with hardening, elastic only (a yield stress never reached), and a frictional one.
inline const char* const kPlastic = "type j2Plasticity; E 2.5; nu 0.3; rho 1; yieldStress 0.02; "
                                    "hardeningModulus 0.2;";
inline const char* const kElasticJ2 = "type j2Plasticity; E 2.5; nu 0.3; rho 1; yieldStress 1e30;";
inline const char* const kDP = "type druckerPrager; E 2.5; nu 0.3; rho 1; frictionAngle 30; "
                               "dilatancyAngle 30; cohesion 0.01;";

// An affine map I + scale (cos terms) (seed: which), and points mapped by one.
template <int D>
Mat<D> affine(double scale, unsigned seed)
{
    Mat<D> A = Mat<D>::Identity();
    for (int i = 0; i < D; ++i)
    {
        for (int j = 0; j < D; ++j)
        {
            A(i, j) += scale * std::cos(seed + 5.0 * i + 3.0 * j);
        }
    }
    return A;
}

template <int D>
std::vector<Vec<D>> mapped(const Mat<D>& A, const std::vector<Vec<D>>& x)
{
    std::vector<Vec<D>> y(x.size());
    for (std::size_t a = 0; a < x.size(); ++a)
    {
        y[a] = A * x[a];
    }
    return y;
}

// A step's motion: smooth plus a random part of `noise` spacings.
template <int D>
std::vector<Vec<D>> step(const std::vector<Vec<D>>& x, double noise, unsigned seed)
{
    std::mt19937 random(seed);
    std::normal_distribution<double> normal;
    std::vector<Vec<D>> y(x);
    for (auto& p : y)
    {
        for (int d = 0; d < D; ++d)
        {
            p[d] += 0.01 * std::sin(0.4 * p.sum() + d) + noise * normal(random);
        }
    }
    return y;
}

// The scheme's force at x is −∂Π/∂x (central differences) and sums to zero (momentum).
template <int D>
void checkForceIsTheGradient(SchemeFixture<D>& f, const std::vector<Vec<D>>& x)
{
    ForceStatus status;
    const auto T = f.forces(x, &status);
    REQUIRE(status.ok());
    Vec<D> total = Vec<D>::Zero();
    double sum = 0.0;
    for (const auto& t : T)
    {
        total += t;
        sum += t.norm();
    }
    REQUIRE(sum > 0.0);
    CHECK(total.cwiseAbs().maxCoeff() < 1e-13 * sum);
    CHECK(largestForceError(f, x, T) / largestComponent<D>(T) < 1e-6);
}

// Samples that carry their elastic state, after two commits and moves of the reference in
// plastic flow: K = 0 at every particle, and the force a step further is −∂Π/∂x (finite
// differences) with zero total.
template <int D>
void checkForceAfterMoves(const std::string& schemeText, const std::string& materialText)
{
    INFO(D << "D " << schemeText << " " << materialText);
    SchemeFixture<D> f(schemeCloud<D>(7), schemeText, materialText, false, schemeHOverDx<D>());
    const auto x1 = deformCurrent<D>(f.ref.x, 17);
    REQUIRE(f.commit(x1) > 0.0);
    REQUIRE(f.moveReference(x1).ok());
    const auto x2 = step<D>(x1, 0.02, 3);
    REQUIRE(f.commit(x2) > 0.0);
    REQUIRE(f.moveReference(x2).ok());
    for (const auto& K : f.ref.K)
    {
        CHECK(K.slice[0].norm() == 0.0);
    }
    checkForceIsTheGradient<D>(f, step<D>(x2, 0.02, 4));
}

// Objectivity through plastic flow and moves of the reference: two runs whose current
// configurations differ by a rotation Q (the initial one is the same) commit, move, commit,
// move and evaluate. The forces rotate; the energy and the dissipation do not change. With
// referenceMoves false the scheme is built as a total-Lagrangian run builds it, and nothing
// moves the reference (gradF's elasticState frames move at the commits, §G25).
template <int D>
void checkObjectiveAfterMoves(const std::string& schemeText, const std::string& materialText,
                              bool referenceMoves = true)
{
    INFO(D << "D " << schemeText << " " << materialText << (referenceMoves ? "" : " (TL)"));
    const auto run = [&](const Mat<D>& Q, std::vector<Vec<D>>& T, double& energy, double& dissipated)
    {
        SchemeFixture<D> f(schemeCloud<D>(7), schemeText, materialText, false, schemeHOverDx<D>(),
                           "cubicSpline", 1, false, referenceMoves);
        const auto rotated = [&Q](const std::vector<Vec<D>>& y)
        {
            std::vector<Vec<D>> z(y.size());
            for (std::size_t a = 0; a < y.size(); ++a)
            {
                z[a] = Q * y[a];
            }
            return z;
        };
        const auto x1 = deformCurrent<D>(f.ref.x, 17);
        const auto x2 = step<D>(x1, 0.02, 3);
        const auto x3 = step<D>(x2, 0.02, 4);
        dissipated = f.commit(rotated(x1));
        REQUIRE((!referenceMoves || f.moveReference(rotated(x1)).ok()));
        dissipated += f.commit(rotated(x2));
        REQUIRE((!referenceMoves || f.moveReference(rotated(x2)).ok()));
        T = f.forces(rotated(x3));
        energy = f.energy(rotated(x3));
    };
    Mat<D> Q = Mat<D>::Identity();
    if constexpr (D == 2)
    {
        Q = Eigen::Rotation2Dd(0.7).toRotationMatrix();
    }
    else
    {
        Q = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    }
    std::vector<Vec<D>> T0, T1;
    double e0, e1, d0, d1;
    run(Mat<D>::Identity(), T0, e0, d0);
    run(Q, T1, e1, d1);
    REQUIRE(d0 > 0.0);
    CHECK(e1 == Approx(e0).epsilon(1e-11));
    CHECK(d1 == Approx(d0).epsilon(1e-11));
    double difference = 0.0;
    for (std::size_t a = 0; a < T0.size(); ++a)
    {
        difference = std::max(difference, (T1[a] - Q * T0[a]).cwiseAbs().maxCoeff());
    }
    CHECK(difference < 1e-10 * largestComponent<D>(T0));
}

// Moves of the reference at yielded, non-uniform states: Π with the new reference (after the
// evaluation that chooses the weights) against Π with the old one at the same positions, the
// largest change relative to Π over three moves; then the force a step later against −∂Π/∂x.
// neverRaises (if not null) is cleared if a move raised Π.
template <int D>
double largestMoveChange(const std::string& schemeText, const std::string& materialText,
                         bool* neverRaises = nullptr)
{
    INFO(D << "D " << schemeText << " " << materialText);
    SchemeFixture<D> f(schemeCloud<D>(7), schemeText, materialText, false, schemeHOverDx<D>());
    auto x = deformCurrent<D>(f.ref.x, 17);
    REQUIRE(f.commit(x) > 0.0);
    double largest = 0.0;
    for (unsigned move = 0; move < 3; ++move)
    {
        const double before = f.energy(x);
        REQUIRE(f.moveReference(x).ok());
        f.forces(x); // the evaluation after the move chooses the weights
        const double after = f.energy(x);
        largest = std::max(largest, std::abs(after - before) / std::abs(before));
        if (neverRaises)
        {
            *neverRaises = *neverRaises && after <= before * (1.0 + 1e-13);
        }
        x = step<D>(x, 0.02, 3 + move);
        REQUIRE(f.commit(x) >= 0.0);
    }
    const auto next = step<D>(x, 0.02, 9);
    const auto T = f.forces(next);
    CHECK(largestForceError(f, next, T) / largestComponent<D>(T) < 1e-6);
    return largest;
}

} // namespace sph::test
