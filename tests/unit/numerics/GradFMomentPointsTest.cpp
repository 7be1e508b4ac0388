// gradF with `samplePoints moments` (docs/theory/gradF-moments.md):
//   - the rule (M3) has the kernel weights' moments of order 0, 1 and 2, with non-negative
//     weights and the particle as point 0, inside a body and at its surface; it declines
//     neighbourhoods that do not span every direction;
//   - for a strain energy quadratic in F (linearElastic) the energy and the forces are the
//     neighbour samples' to round-off (§M1), total and updated Lagrangian; for neoHookean they
//     are not (the check has teeth);
//   - the force is the exact −∂Π/∂x (finite differences) with zero total: elastic in TL and
//     after a reference move, plastic (J2, Drucker-Prager) in TL after commits in flow (§M3-§M4);
//   - a material with history under updated Lagrangian is refused (§M4);
//   - several particles' points evaluated together (one block of lanes) change no digit.
#include "core/InputError.hpp"
#include "numerics/PlasticMotion.hpp"
#include "numerics/PlasticPoints.hpp"
#include "stabilisation/gradF/GradF.hpp"
#include "stabilisation/gradF/MomentPoints.hpp"

using namespace sph;

namespace
{

const char* kMoments = "type gradF; samplePoints moments;";
const char* kLinear = "type linearElastic; E 2.5; nu 0.3; rho 1;";
const char* kNeoHookean = "type neoHookean; mu 1; kappa 5; rho 1;";

// Particle a's offsets and kernel weights as gradF's kinematics makes them.
template <int D>
void neighbourhood(const test::SchemeFixture<D>& f, std::size_t a, std::vector<Vec<D>>& xr,
                   std::vector<double>& w)
{
    const NeighbourList& list = f.ref.neighbours;
    const double* W = f.ref.kernelValues(a).W;
    xr.clear();
    w.clear();
    double denominator = 0.0;
    for (std::size_t j = 0; j < list.count(a); ++j)
    {
        denominator += W[j] * f.ref.V[list.indices[list.begin(a) + j]];
    }
    for (std::size_t j = 0; j < list.count(a); ++j)
    {
        const std::size_t b = list.indices[list.begin(a) + j];
        xr.push_back(f.ref.x[b] - f.ref.x[a]);
        w.push_back(W[j] * f.ref.V[b] / denominator);
    }
}

template <int D>
void rulesMoments()
{
    INFO(D << "D");
    constexpr int count = MomentPoints<D>::count;
    test::SchemeFixture<D> f(test::schemeCloud<D>(7), kMoments, kNeoHookean, false,
                             test::schemeHOverDx<D>());
    std::vector<Vec<D>> xr;
    std::vector<double> w;
    double largestOffCentre = 0.0;
    double smallestParticleWeight = 1.0;
    for (std::size_t a = 0; a < f.ref.size(); ++a)
    {
        neighbourhood(f, a, xr, w);
        Vec<D> points[count];
        double weights[count];
        REQUIRE(momentPoints<D>(xr.data(), w.data(), xr.size(), points, weights));
        double W0 = 0.0, Wq = 0.0;
        Vec<D> m0 = Vec<D>::Zero(), mq = Vec<D>::Zero();
        Mat<D> M0 = Mat<D>::Zero(), Mq = Mat<D>::Zero();
        for (std::size_t j = 0; j < xr.size(); ++j)
        {
            W0 += w[j];
            m0 += w[j] * xr[j];
            M0 += w[j] * xr[j] * xr[j].transpose();
        }
        for (int q = 0; q < count; ++q)
        {
            CHECK(weights[q] >= 0.0);
            Wq += weights[q];
            mq += weights[q] * points[q];
            Mq += weights[q] * points[q] * points[q].transpose();
        }
        CHECK(points[0].norm() == 0.0);
        CHECK(std::abs(Wq - W0) < 1e-14);
        CHECK((mq - m0).norm() < 1e-14 * std::sqrt(M0.trace()));
        CHECK((Mq - M0).norm() < 1e-13 * M0.norm());
        largestOffCentre = std::max(largestOffCentre, m0.norm() / std::sqrt(M0.trace()));
        smallestParticleWeight = std::min(smallestParticleWeight, weights[0] / W0);
    }
    // The cloud has a surface (one-sided neighbourhoods); in 2D the particle's weight is
    // lowered there below 1 − D/3 (in 3D it is 0 everywhere).
    CHECK(largestOffCentre > 0.3);
    if constexpr (D == 2)
    {
        CHECK(smallestParticleWeight < MomentPoints<D>::particleWeight - 0.05);
    }
}

// Too few neighbours, or all of them on a line: no rule (the particle keeps its neighbours).
void declinesFlatNeighbourhoods()
{
    Vec<2> points[5];
    double weights[5];
    std::vector<Vec<2>> line{Vec<2>::Zero(), Vec<2>(1, 0), Vec<2>(-1, 0), Vec<2>(2, 0), Vec<2>(-2, 0)};
    std::vector<double> w(line.size(), 0.2);
    CHECK_FALSE(momentPoints<2>(line.data(), w.data(), line.size(), points, weights));
    std::vector<Vec<2>> few{Vec<2>::Zero(), Vec<2>(1, 0), Vec<2>(0, 1), Vec<2>(-1, 0)};
    CHECK_FALSE(momentPoints<2>(few.data(), w.data(), few.size(), points, weights));
    std::vector<Vec<2>> cross{Vec<2>::Zero(), Vec<2>(1, 0), Vec<2>(-1, 0), Vec<2>(0, 1), Vec<2>(0, -1)};
    REQUIRE(momentPoints<2>(cross.data(), w.data(), cross.size(), points, weights));
    CHECK(weights[0] == Approx(1.0 / 3.0).epsilon(1e-15)); // Σ w = 1, symmetric: ω_0 = 1 − 2/3
}

template <int D>
double relativeForceDifference(const std::vector<Vec<D>>& T1, const std::vector<Vec<D>>& T2)
{
    double difference = 0.0;
    for (std::size_t a = 0; a < T1.size(); ++a)
    {
        difference = std::max(difference, (T1[a] - T2[a]).cwiseAbs().maxCoeff());
    }
    return difference / test::largestComponent<D>(T1);
}

template <int D>
void quadraticEnergyIsTheNeighbours(bool updated)
{
    INFO(D << "D, " << (updated ? "updated" : "total") << " Lagrangian");
    const auto energies = [updated](const char* material, double& relative, double& forces)
    {
        test::SchemeFixture<D> neighbours(test::schemeCloud<D>(7), "type gradF;", material, updated,
                                          test::schemeHOverDx<D>());
        test::SchemeFixture<D> moments(test::schemeCloud<D>(7), kMoments, material, updated,
                                       test::schemeHOverDx<D>());
        const auto x = test::deformCurrent<D>(neighbours.ref.x, 17);
        const double e1 = neighbours.energy(x);
        const double e2 = moments.energy(x);
        REQUIRE(e1 > 0.0);
        relative = std::abs(e2 - e1) / e1;
        forces = relativeForceDifference<D>(neighbours.forces(x), moments.forces(x));
    };
    double relative = 0.0, forces = 0.0;
    energies(kLinear, relative, forces);
    CHECK(relative < 1e-12);
    CHECK(forces < 1e-10);
    energies(kNeoHookean, relative, forces); // not quadratic in F: a different quadrature
    CHECK(relative > 1e-8);
    CHECK(forces > 1e-6);
}

template <int D>
void forceIsTheGradient()
{
    INFO(D << "D");
    {
        test::SchemeFixture<D> f(test::schemeCloud<D>(7), kMoments, kNeoHookean, false,
                                 test::schemeHOverDx<D>(), "cubicSpline", 1, false, false);
        test::checkForceIsTheGradient<D>(f, test::deformCurrent<D>(f.ref.x, 17));
    }
    {
        // Updated Lagrangian, elastic: the points of the moved reference.
        test::SchemeFixture<D> f(test::schemeCloud<D>(7), kMoments, kNeoHookean, true,
                                 test::schemeHOverDx<D>());
        const auto x1 = test::deformCurrent<D>(f.ref.x, 17);
        f.forces(x1);
        REQUIRE(f.moveReference(x1).ok());
        test::checkForceIsTheGradient<D>(f, test::step<D>(x1, 0.02, 5));
    }
    for (const char* plastic : {test::kPlastic, test::kDP})
    {
        INFO(plastic);
        test::SchemeFixture<D> f(test::schemeCloud<D>(7), kMoments, plastic, false,
                                 test::schemeHOverDx<D>(), "cubicSpline", 1, false, false);
        const auto x1 = test::deformCurrent<D>(f.ref.x, 17);
        REQUIRE(f.commit(x1) > 0.0);
        const auto x2 = test::step<D>(x1, 0.02, 3);
        REQUIRE(f.commit(x2) > 0.0);
        test::checkForceIsTheGradient<D>(f, test::step<D>(x2, 0.02, 4));
    }
}

// Several particles' moment points evaluated in one call of a plastic material (sampleGroup)
// change no digit: forces, F, P, energy and dissipation through commits in flow, against the
// same evaluations particle by particle.
template <int D>
void groupedIsOneByOne(const char* plastic)
{
    INFO(D << "D " << plastic);
    const auto run = [plastic](bool grouped, std::vector<Vec<D>>& T, std::vector<Mat<D>>& P,
                               double& energy, double& dissipated)
    {
        test::SchemeFixture<D> f(test::schemeCloud<D>(7), kMoments, plastic, false,
                                 test::schemeHOverDx<D>(), "cubicSpline", 1, false, false);
        auto* gradF = dynamic_cast<GradF<D>*>(f.scheme.get());
        REQUIRE(gradF);
        gradF->groupSampleEvaluations(grouped);
        const auto x1 = test::deformCurrent<D>(f.ref.x, 17);
        const auto x2 = test::step<D>(x1, 0.02, 3);
        dissipated = f.commit(x1);
        dissipated += f.commit(x2);
        const auto x3 = test::step<D>(x2, 0.02, 4);
        std::vector<Mat<D>> F;
        ForceOutput<D> out{T, F, P};
        REQUIRE(f.scheme->computeForces(f.input(x3), out, true).ok());
        energy = f.energy(x3);
    };
    std::vector<Vec<D>> T1, T2;
    std::vector<Mat<D>> P1, P2;
    double e1 = 0.0, e2 = 0.0, d1 = 0.0, d2 = 0.0;
    run(false, T1, P1, e1, d1);
    run(true, T2, P2, e2, d2);
    REQUIRE(d1 > 0.0);
    CHECK(test::sameBits(e1, e2));
    CHECK(test::sameBits(d1, d2));
    REQUIRE(T1.size() == T2.size());
    for (std::size_t a = 0; a < T1.size(); ++a)
    {
        CHECK(test::sameBits(T1[a], T2[a]));
        CHECK(test::sameBits(P1[a], P2[a]));
    }
}

} // namespace

TEST_CASE("gradF samplePoints moments: particles evaluated in groups, bit for bit",
          "[gradF][moments]")
{
    for (const char* plastic : {test::kPlastic, test::kDP})
    {
        groupedIsOneByOne<2>(plastic);
        groupedIsOneByOne<3>(plastic);
    }
}

TEST_CASE("gradF moment points: the kernel weights' moments up to the second", "[gradF][moments]")
{
    rulesMoments<2>();
    rulesMoments<3>();
    declinesFlatNeighbourhoods();
}

TEST_CASE("gradF samplePoints moments: a quadratic energy is the neighbour samples'",
          "[gradF][moments]")
{
    quadraticEnergyIsTheNeighbours<2>(false);
    quadraticEnergyIsTheNeighbours<2>(true);
    quadraticEnergyIsTheNeighbours<3>(false);
    quadraticEnergyIsTheNeighbours<3>(true);
}

TEST_CASE("gradF samplePoints moments: the force is -dPi/dx, elastic and in plastic flow",
          "[gradF][moments]")
{
    forceIsTheGradient<2>();
    forceIsTheGradient<3>();
}

TEST_CASE("gradF samplePoints moments: plastic history under updated Lagrangian is refused",
          "[gradF][moments]")
{
    REQUIRE_THROWS_AS(test::SchemeFixture<2>(test::schemeCloud<2>(7), kMoments, test::kPlastic, false,
                                             test::schemeHOverDx<2>()),
                      InputError);
}
