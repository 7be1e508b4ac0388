// The probe of the operator's largest frequency (docs/theory/timeStep.md §T3): on a chain of
// springs it converges to the analytic largest frequency and never exceeds it; after a change
// of the operator the warm-started probe finds the new stiffest mode, also where the kept mode
// had no component; on a CSPH cloud (gradF, yielding material) it equals the largest eigenvalue
// of the assembled stiffness; fixed particles are not degrees of freedom.
#include "numerics/NumericsSupport.hpp"
#include "timeIntegration/TimeIntegration.hpp"

#include <Eigen/Eigenvalues>


#include <cmath>

using namespace sph;

namespace
{

const ParticleRanks serial; // every particle owned, no reductions

// A chain of n masses on a line joined by springs (stiffness k[i] between i and i+1); the two
// end particles are fixed. The force along the line.
struct SpringChain
{
    std::vector<double> k;
    std::vector<double> m;
    std::vector<std::uint8_t> fixed;
    std::vector<Vec<1>> x;

    explicit SpringChain(std::size_t n) : k(n - 1, 4.0), m(n, 2.0), fixed(n, 0), x(n)
    {
        fixed.front() = fixed.back() = 1;
        for (std::size_t i = 0; i < n; ++i)
        {
            x[i][0] = static_cast<double>(i);
        }
    }
    void forces(const std::vector<Vec<1>>& at, std::vector<Vec<1>>& T) const
    {
        T.assign(at.size(), Vec<1>::Zero());
        for (std::size_t i = 0; i + 1 < at.size(); ++i)
        {
            const double f = k[i] * (at[i + 1][0] - at[i][0] - 1.0); // tension
            T[i][0] += f;
            T[i + 1][0] -= f;
        }
    }
    // ω_max from the dense eigenvalues of M^(-1/2) K M^(-1/2) over the free particles.
    double largestFrequency() const
    {
        const std::size_t n = x.size() - 2;
        Eigen::MatrixXd A = Eigen::MatrixXd::Zero(static_cast<long>(n), static_cast<long>(n));
        for (std::size_t i = 0; i + 1 < x.size(); ++i)
        {
            // spring between particles i and i+1 (free indices i-1 and i)
            const long a = static_cast<long>(i) - 1;
            const long b = static_cast<long>(i);
            if (a >= 0)
            {
                A(a, a) += k[i];
            }
            if (b < static_cast<long>(n))
            {
                A(b, b) += k[i];
            }
            if (a >= 0 && b < static_cast<long>(n))
            {
                A(a, b) -= k[i];
                A(b, a) -= k[i];
            }
        }
        for (long a = 0; a < static_cast<long>(n); ++a)
        {
            for (long b = 0; b < static_cast<long>(n); ++b)
            {
                A(a, b) /= std::sqrt(m[static_cast<std::size_t>(a) + 1] * m[static_cast<std::size_t>(b) + 1]);
            }
        }
        return std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues().maxCoeff());
    }
    OperatorProbe<1>::Result probe(int iterations, std::vector<Vec<1>>& mode, long step) const
    {
        std::vector<Vec<1>> T0;
        forces(x, T0);
        return OperatorProbe<1>::run({x, T0, m, fixed, 1.0, step, serial},
                                     [this](const std::vector<Vec<1>>& at, std::vector<Vec<1>>& T) {
                                         forces(at, T);
                                     },
                                     iterations, mode);
    }
};

} // namespace

TEST_CASE("operator probe: the largest frequency of a chain of springs", "[operatorProbe]")
{
    SpringChain chain(12); // 10 free masses
    // Analytic: ω_j = 2 √(k/m) sin(jπ/(2(N+1))), N = 10, j = N.
    const double exact = 2.0 * std::sqrt(4.0 / 2.0) * std::sin(10.0 * M_PI / 22.0);
    REQUIRE(chain.largestFrequency() == Approx(exact).epsilon(1e-12));
    std::vector<Vec<1>> mode;
    double previous = 0.0;
    for (int probe = 0; probe < 40; ++probe)
    {
        const double omega = chain.probe(5, mode, probe).omega;
        // |A y|/|y| of a symmetric positive semi-definite A never exceeds λ_max (§T3).
        CHECK(omega <= exact * (1.0 + 1e-6));
        previous = omega;
    }
    CHECK(previous == Approx(exact).epsilon(1e-3));
    // Fixed particles are not degrees of freedom.
    CHECK(mode.front()[0] == 0.0);
    CHECK(mode.back()[0] == 0.0);
}

TEST_CASE("operator probe: a warm start finds a newly stiffest mode elsewhere", "[operatorProbe]")
{
    SpringChain chain(42);
    std::vector<Vec<1>> mode;
    chain.probe(50, mode, 0);
    for (int probe = 1; probe < 20; ++probe)
    {
        chain.probe(2, mode, probe);
    }
    // One spring near the end becomes 9 times stiffer: the new largest frequency is local there,
    // three times the old, where the kept mode (the chain's zig-zag) is small.
    chain.k[36] *= 9.0;
    const double exact = chain.largestFrequency();
    double omega = 0.0;
    int probes = 0;
    while (probes < 10 && !(omega > 0.95 * exact))
    {
        omega = chain.probe(2, mode, 100 + probes).omega;
        ++probes;
    }
    CHECK(omega > 0.95 * exact);
    CHECK(omega <= exact * (1.0 + 1e-6));
    CHECK(probes <= 3); // two products per probe find it within three probes
    const std::size_t where = chain.probe(2, mode, 200).where;
    CHECK((where == 36 || where == 37));
}

TEST_CASE("operator probe: the same step draws the same numbers, another step others",
          "[operatorProbe]")
{
    SpringChain chain(12);
    std::vector<Vec<1>> a;
    std::vector<Vec<1>> b;
    std::vector<Vec<1>> c;
    chain.probe(1, a, 7);
    chain.probe(1, b, 7);
    chain.probe(1, c, 8);
    CHECK(a == b);
    CHECK(a != c);
}

// On a perturbed 2D lattice with the gradient-of-F scheme and a yielding material, at a deformed
// state: the probe's ω̃ against the largest eigenvalue of M^(-1/2) K M^(-1/2), K assembled by
// central differences of the scheme's force (each column one particle direction).
TEST_CASE("operator probe: the largest frequency of a gradF cloud", "[operatorProbe]")
{
    const auto X = test::schemeCloud<2>(6);
    test::SchemeFixture<2> fixture(X, "type gradF;",
                                   "type j2Plasticity; E 2.5; nu 0.3; rho 1; yieldStress 0.02; "
                                   "hardeningModulus 0.2;",
                                   false);
    const std::vector<Vec<2>> x = test::deformCurrent<2>(X, 3);
    const std::size_t n = x.size();
    std::vector<double> m(n);
    for (std::size_t a = 0; a < n; ++a)
    {
        m[a] = 1.0 + 0.5 * static_cast<double>(a % 3);
    }
    const std::vector<std::uint8_t> fixed(n, 0);
    const auto forcesAt = [&fixture](const std::vector<Vec<2>>& at, std::vector<Vec<2>>& T) {
        T = fixture.forces(at);
    };
    std::vector<Vec<2>> T0;
    forcesAt(x, T0);

    const long dofs = static_cast<long>(2 * n);
    Eigen::MatrixXd A(dofs, dofs);
    const double step = 1e-6;
    for (std::size_t b = 0; b < n; ++b)
    {
        for (int j = 0; j < 2; ++j)
        {
            std::vector<Vec<2>> plus = x;
            std::vector<Vec<2>> minus = x;
            plus[b][j] += step;
            minus[b][j] -= step;
            std::vector<Vec<2>> Tp;
            std::vector<Vec<2>> Tm;
            forcesAt(plus, Tp);
            forcesAt(minus, Tm);
            for (std::size_t a = 0; a < n; ++a)
            {
                for (int i = 0; i < 2; ++i)
                {
                    A(static_cast<long>(2 * a) + i, static_cast<long>(2 * b) + j) =
                        -(Tp[a][i] - Tm[a][i]) / (2.0 * step) / std::sqrt(m[a] * m[b]);
                }
            }
        }
    }
    // The force is -∂Π/∂x: K is symmetric (to the differences' error).
    CHECK((A - A.transpose()).norm() < 1e-5 * A.norm());
    const Eigen::MatrixXd symmetric = 0.5 * (A + A.transpose());
    const double exact =
        std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(symmetric).eigenvalues().maxCoeff());

    std::vector<Vec<2>> mode;
    const auto result =
        OperatorProbe<2>::run({x, T0, m, fixed, fixture.kernel->h(), 0, serial}, forcesAt, 300, mode);
    CHECK(result.omega == Approx(exact).epsilon(1e-3));
}

// The rule (T4.1) of `stepBound operator` in the leapfrog, with a stand-in for the solver's
// probe: the first level takes the wave-speed step and keeps κ = ω̃_0 Δt_0; a probe that
// measures twice the frequency halves the step, half the frequency doubles it unless the walls'
// cap is lower; between probes the step is kept; a frequency that explodes is a collapse.
TEST_CASE("stepBound operator: the step keeps the first level's margin, capped by the walls",
          "[operatorProbe]")
{
    auto leapfrog = test::build<TimeIntegration<1>>(
        "type leapfrog; stepBound operator; probeInterval 5;", {0.3, 1}, 1);
    ParticleFields<1> fields;
    fields.setSize(3);
    RunScalars scalars;
    std::vector<Vec<1>> v(3, Vec<1>::Zero());
    leapfrog->attach(v, fields, scalars);
    double omega = 1000.0;
    leapfrog->setOperatorFrequency([&omega](int, std::vector<Vec<1>>&) {
        return OperatorProbe<1>::Result{omega, 1};
    });
    WaveSpeedBound bound{0.01, [] { return 100.0; }, [] { return std::size_t{0}; }};
    REQUIRE(leapfrog->chooseTimeStep(0, true, bound).ok());
    const double first = 0.3 * 0.01 / 100.0;
    CHECK(leapfrog->deltaT() == Approx(first));
    omega = 2000.0; // stiffer: half the step, at the next probe only
    REQUIRE(leapfrog->chooseTimeStep(3, false, bound).ok());
    CHECK(leapfrog->deltaT() == Approx(first));
    REQUIRE(leapfrog->chooseTimeStep(5, false, bound).ok());
    CHECK(leapfrog->deltaT() == Approx(0.5 * first));
    omega = 500.0; // softer: twice the step without walls...
    REQUIRE(leapfrog->chooseTimeStep(10, false, bound).ok());
    CHECK(leapfrog->deltaT() == Approx(2.0 * first));
    bound.wallDeltaT = 1.2 * first; // ...and the walls' cap with them
    REQUIRE(leapfrog->chooseTimeStep(15, false, bound).ok());
    CHECK(leapfrog->deltaT() == Approx(1.2 * first));
    omega = 1e12;
    CHECK(leapfrog->chooseTimeStep(20, false, bound).failure == FailureKind::timeStepCollapse);
}
