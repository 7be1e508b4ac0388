// gradF with `sampleVolume particle` (docs/theory/gradF-plastic.md §G13): every stress sample of
// particle a takes a's volume, F̄_b(a) = (J_a / det F_b(a))^(1/D) F_b(a), the F-bar method.
//   - the force is the exact −∂Π/∂x of Π = Σ_a V0_a Σ_b Ŵ_ab Ψ(F̄_b(a)) (finite differences):
//     elastic, total Lagrangian and after reference moves; plastic with elasticState samples
//     after moves; with zero total (momentum);
//   - an affine motion is the paper's gradF (G = 0: α = 1): the energy to round-off, the force
//     where the neighbourhoods are symmetric; a non-affine one is not (the test has teeth);
//   - objective: a rotated, yielded configuration rotates the forces and changes no scalar;
//   - every sample of a particle has the particle's volume, det F̄_b(a) = J_a;
//   - a material without history (neoHookean) keeps the paper's samples, bit for bit.
#include "numerics/PlasticMotion.hpp"
#include "stabilisation/gradF/GradF.hpp"

using namespace sph;

namespace
{

// F-bar acts on the particles of a material with history: a J2 material that never yields is
// elastic with it on; neoHookean keeps the paper's samples.
const char* kElastic = "type j2Plasticity; E 2.5; nu 0.3; rho 1; yieldStress 1e30;";
const char* kNeoHookean = "type neoHookean; mu 1; kappa 5; rho 1;";
const char* kPlastic = "type j2Plasticity; E 2.5; nu 0.3; rho 1; yieldStress 0.02; "
                       "hardeningModulus 0.2;";
const char* kAssociativeDP = "type druckerPrager; E 2.5; nu 0.3; rho 1; frictionAngle 30; "
                             "dilatancyAngle 30; cohesion 0.01;";
const char* kParticle = "type gradF; sampleVolume particle;";
const char* kParticleElasticState = "type gradF; sampleVolume particle; plasticSamples elasticState;";

template <int D>
void elasticForce(bool updated)
{
    INFO(D << "D, " << (updated ? "updated" : "total") << " Lagrangian");
    test::SchemeFixture<D> f(test::schemeCloud<D>(7), kParticle, kElastic, updated,
                             test::schemeHOverDx<D>());
    const auto x1 = test::deformCurrent<D>(f.ref.x, 17);
    if (updated)
    {
        f.forces(x1);
        REQUIRE(f.moveReference(x1).ok());
    }
    test::checkForceIsTheGradient<D>(f, test::step<D>(x1, 0.02, 5));
}

// For an affine motion every sample is F_a (G = 0, α = 1): the energy is the paper's to
// round-off, and so is the force where the neighbourhoods are symmetric (Σ_b Ŵ_ab x^r_ba = 0:
// (G13.2) moves p̃ F_a^{-T} from the G-derivative to the F-derivative, which differ only by that
// sum). A non-affine motion differs (the check has teeth).
template <int D>
void affineIsThePapers()
{
    INFO(D << "D");
    Mat<D> A = Mat<D>::Identity();
    for (int i = 0; i < D; ++i)
    {
        for (int j = 0; j < D; ++j)
        {
            A(i, j) += 0.2 * std::cos(3.0 + 5.0 * i + 3.0 * j);
        }
    }
    const auto mapped = [&A](const std::vector<Vec<D>>& cloud)
    {
        std::vector<Vec<D>> x(cloud.size());
        for (std::size_t a = 0; a < cloud.size(); ++a)
        {
            x[a] = A * cloud[a];
        }
        return x;
    };
    const auto fixtures = [](const std::vector<Vec<D>>& cloud)
    {
        return std::make_pair(
            std::make_unique<test::SchemeFixture<D>>(cloud, "type gradF;", kElastic, false,
                                                     test::schemeHOverDx<D>()),
            std::make_unique<test::SchemeFixture<D>>(cloud, kParticle, kElastic, false,
                                                     test::schemeHOverDx<D>()));
    };
    {
        const auto cloud = test::schemeCloud<D>(7); // perturbed
        auto [own, particle] = fixtures(cloud);
        const auto x = mapped(cloud);
        CHECK(particle->energy(x) == Approx(own->energy(x)).epsilon(1e-13));
        const auto y = test::deformCurrent<D>(cloud, 17);
        CHECK(std::abs(particle->energy(y) - own->energy(y)) > 1e-4 * own->energy(y));
    }
    // A particle's force involves its neighbours' sums over theirs: two supports (4h) from the
    // edge its neighbourhood and theirs are symmetric.
    const double margin = 4.0 * test::schemeHOverDx<D>() + 1e-9;
    const int n = static_cast<int>(std::ceil(2.0 * margin)) + 2;
    const auto cloud = test::lattice<D>(n, 0.0, 5); // regular: symmetric in the interior
    auto [own, particle] = fixtures(cloud);
    const auto x = mapped(cloud);
    const auto T0 = own->forces(x);
    const auto T1 = particle->forces(x);
    Vec<D> lo = cloud[0], hi = cloud[0];
    for (const auto& p : cloud)
    {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    double difference = 0.0;
    std::size_t interior = 0;
    for (std::size_t a = 0; a < cloud.size(); ++a)
    {
        if ((cloud[a] - lo).minCoeff() < margin || (hi - cloud[a]).minCoeff() < margin)
        {
            continue;
        }
        ++interior;
        difference = std::max(difference, (T1[a] - T0[a]).cwiseAbs().maxCoeff());
    }
    REQUIRE(interior > 0);
    CHECK(difference < 1e-12 * test::largestComponent<D>(T0));
}

// det F̄_b(a) = J_a for every sample of every particle, on a distorted cloud.
template <int D>
void samplesHaveTheParticlesVolume()
{
    INFO(D << "D");
    test::SchemeFixture<D> f(test::schemeCloud<D>(7), kParticle, kElastic, false,
                             test::schemeHOverDx<D>());
    const auto& scheme = dynamic_cast<const GradF<D>&>(*f.scheme);
    const auto x = test::deformCurrent<D>(f.ref.x, 23);
    double spread = 0.0; // of the samples' own volumes: the check has teeth
    for (std::size_t a = 0; a < x.size(); ++a)
    {
        typename GradF<D>::Scratch scratch;
        const std::size_t count = f.ref.neighbours.count(a);
        scratch.resize(count);
        const auto kin = scheme.kinematics(a, x, f.ref, false, scratch);
        const double Ja = kin.F.determinant();
        REQUIRE(scheme.fillSamples(kin, count, scratch, true) > 0.0);
        for (std::size_t j = 0; j < count; ++j)
        {
            CHECK(scratch.F[j].determinant() == Approx(Ja).epsilon(1e-13));
            spread = std::max(spread, std::abs(std::pow(scratch.alpha[j], D) - 1.0));
        }
    }
    CHECK(spread > 1e-3);
}

} // namespace

TEST_CASE("gradF sampleVolume particle: force = -dPi/dx, elastic, total and updated Lagrangian",
          "[gradF][sampleVolume]")
{
    test::loadModelLibraries();
    for (const bool updated : {false, true})
    {
        elasticForce<2>(updated);
        elasticForce<3>(updated);
    }
}

TEST_CASE("gradF sampleVolume particle: force = -dPi/dx with elasticState samples after moves",
          "[gradF][sampleVolume][plasticity]")
{
    test::loadModelLibraries();
    test::checkForceAfterMoves<2>(kParticleElasticState, kPlastic);
    test::checkForceAfterMoves<3>(kParticleElasticState, kPlastic);
    test::checkForceAfterMoves<2>(kParticleElasticState, kAssociativeDP);
}

TEST_CASE("gradF sampleVolume particle: the paper's gradF for an affine motion", "[gradF][sampleVolume]")
{
    test::loadModelLibraries();
    affineIsThePapers<2>();
    affineIsThePapers<3>();
}

TEST_CASE("gradF sampleVolume particle: every sample has the particle's volume",
          "[gradF][sampleVolume]")
{
    test::loadModelLibraries();
    samplesHaveTheParticlesVolume<2>();
    samplesHaveTheParticlesVolume<3>();
}

TEST_CASE("gradF sampleVolume particle: objective (a rotated, yielded configuration)",
          "[gradF][sampleVolume][plasticity]")
{
    test::loadModelLibraries();
    test::checkObjectiveAfterMoves<2>(kParticleElasticState, kPlastic);
    test::checkObjectiveAfterMoves<3>(kParticleElasticState, kPlastic);
}

TEST_CASE("gradF sampleVolume particle: an elastic material without history is the paper's gradF "
          "bit for bit",
          "[gradF][sampleVolume]")
{
    test::loadModelLibraries();
    const auto cloud = test::schemeCloud<2>(7);
    test::SchemeFixture<2> own(cloud, "type gradF;", kNeoHookean, false, test::schemeHOverDx<2>());
    test::SchemeFixture<2> particle(cloud, kParticle, kNeoHookean, false, test::schemeHOverDx<2>());
    const auto x = test::deformCurrent<2>(cloud, 17);
    CHECK(particle.forces(x) == own.forces(x));
    CHECK(particle.energy(x) == own.energy(x));
    // and with history it does differ (the check has teeth)
    test::SchemeFixture<2> j2own(cloud, "type gradF;", kElastic, false, test::schemeHOverDx<2>());
    test::SchemeFixture<2> j2particle(cloud, kParticle, kElastic, false, test::schemeHOverDx<2>());
    CHECK(j2particle.forces(x) != j2own.forces(x));
}
