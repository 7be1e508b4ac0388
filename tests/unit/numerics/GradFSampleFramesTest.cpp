// gradF's elasticState samples in total-Lagrangian form (docs/theory/gradF-plastic.md §G25-§G26):
// each particle's frame (F°, x° of the last commit), the samples of the step's increment in it
// with its gradient fitted there (G26.1, G26.2 / G26.4), the frames moved at each commit with
// every sample's elastic state kept:
//   - the first step is the paper's: before any commit every force and energy equals
//     ownHistory's bit for bit (the joint fit's forces to round-off); along affine motions
//     (H° = 0) after commits too, to round-off;
//   - a commit moves the frames and keeps Π (every sample's be), where the samples differ from
//     F_a; in plastic flow Π after the commit is the paper's after the same commit;
//   - force = −∂Π/∂x between commits, with frames that are not the reference's, both fits;
//   - objective: a rotated, yielded configuration rotates the forces, no scalar changes;
//   - admissible: after steps on a distorted cloud every sample has det > 0, at the cloud's
//     one-sided edge too.
#include "numerics/NumericsSupport.hpp"
#include "numerics/PlasticMotion.hpp"
#include "stabilisation/gradF/GradF.hpp"

using namespace sph;
using sph::test::affine;
using sph::test::mapped;
using sph::test::kDP;
using sph::test::kElasticJ2;
using sph::test::kPlastic;

namespace
{

const char* kFramed = "type gradF; plasticSamples elasticState;";
const char* kFramedJoint = "type gradF; plasticSamples elasticState; fit joint;";

// A total-Lagrangian scheme (Args::referenceMoves false) on the perturbed cloud, x^r = X.
template <int D>
struct TotalLagrangian : test::SchemeFixture<D>
{
    TotalLagrangian(const std::string& scheme, const std::string& material)
        : test::SchemeFixture<D>(test::schemeCloud<D>(7), scheme, material, false,
                                 test::schemeHOverDx<D>(), "cubicSpline", 1, false, false)
    {
    }
};

template <int D>
double largestDifference(const std::vector<Vec<D>>& a, const std::vector<Vec<D>>& b)
{
    double value = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        value = std::max(value, (a[i] - b[i]).cwiseAbs().maxCoeff());
    }
    return value;
}

template <int D>
void firstStepIsThePapers(const std::string& framedText, const std::string& paperText,
                          const char* material)
{
    INFO(D << "D " << framedText << " " << material);
    TotalLagrangian<D> framed(framedText, material);
    TotalLagrangian<D> paper(paperText, material);
    const auto x1 = test::deformCurrent<D>(framed.ref.x, 17);
    const auto T = framed.forces(x1);
    CHECK(T == paper.forces(x1));
    CHECK(framed.energy(x1) == paper.energy(x1));
    // Along affine motions G = 0 and every sample is F_a, commits and frames included.
    TotalLagrangian<D> framedAffine(framedText, material);
    TotalLagrangian<D> paperAffine(paperText, material);
    for (const unsigned seed : {3u, 4u})
    {
        const auto x = mapped<D>(affine<D>(0.04 * seed, seed), framedAffine.ref.x);
        REQUIRE(framedAffine.commit(x) > 0.0); // it yields: the states carry plastic strain
        REQUIRE(paperAffine.commit(x) > 0.0);
    }
    const auto x3 = mapped<D>(affine<D>(0.2, 5), framedAffine.ref.x);
    const auto Tf = framedAffine.forces(x3);
    CHECK(largestDifference<D>(Tf, paperAffine.forces(x3)) < 1e-11 * test::largestComponent<D>(Tf));
    CHECK(framedAffine.energy(x3) == Approx(paperAffine.energy(x3)).epsilon(1e-11));
}

// (G4.1) at a frame move: Π at the committed positions is what it was before the commit (an
// elastic-range material: the commit changes no be), also after a second step from frames that
// are no longer the reference's; the samples there differ from F_a (Π is not `none`'s), so a
// move that did not rebase would change it. In plastic flow, Π after a commit is the paper's
// after the same commit (the first step's samples are the paper's, and the rebase keeps each
// returned be).
template <int D>
void frameMoveKeepsTheEnergy()
{
    INFO(D << "D");
    TotalLagrangian<D> f(kFramed, kElasticJ2);
    TotalLagrangian<D> none("type none;", kElasticJ2);
    const auto x1 = test::deformCurrent<D>(f.ref.x, 17);
    const double before = f.energy(x1);
    CHECK(std::abs(before - none.energy(x1)) > 1e-4 * before);
    f.commit(x1);
    CHECK(f.energy(x1) == Approx(before).epsilon(1e-12));
    const auto x2 = test::step<D>(x1, 0.02, 3);
    const double before2 = f.energy(x2);
    f.commit(x2);
    CHECK(f.energy(x2) == Approx(before2).epsilon(1e-12));

    TotalLagrangian<D> plastic(kFramed, kPlastic);
    TotalLagrangian<D> paper("type gradF;", kPlastic);
    REQUIRE(plastic.commit(x1) > 0.0);
    REQUIRE(paper.commit(x1) > 0.0);
    CHECK(plastic.energy(x1) == Approx(paper.energy(x1)).epsilon(1e-11));
}

// The first step with the joint fit: F_a is the joint fit's and H°_a the least squares with f_a
// fixed, which is the joint fit's own H_a (the joint minimum is the minimum over H at its f), so
// energy and forces are the paper's joint fit's to round-off, on a general motion.
template <int D>
void firstJointStepIsThePapers(const char* material)
{
    INFO(D << "D " << material);
    TotalLagrangian<D> framed(kFramedJoint, material);
    TotalLagrangian<D> paper("type gradF; fit joint;", material);
    const auto x = test::deformCurrent<D>(framed.ref.x, 17);
    CHECK(framed.energy(x) == Approx(paper.energy(x)).epsilon(1e-12));
    const auto T = framed.forces(x);
    CHECK(largestDifference<D>(T, paper.forces(x)) < 1e-10 * test::largestComponent<D>(T));
}

// Every sample of every particle has det > 0 after a distortion and steps; the cloud's edge
// (one-sided supports: a first moment of the weights beyond a tenth of a spacing) is among them.
template <int D>
void samplesAdmissible(const char* schemeText)
{
    INFO(D << "D " << schemeText);
    TotalLagrangian<D> f(schemeText, kPlastic);
    auto& scheme = dynamic_cast<GradF<D>&>(*f.scheme);
    auto x = test::deformCurrent<D>(f.ref.x, 29);
    REQUIRE(f.commit(x) > 0.0);
    std::size_t oneSided = 0;
    for (const unsigned seed : {3u, 4u, 5u})
    {
        x = test::step<D>(x, 0.05, seed);
        ForceStatus status;
        f.forces(x, &status);
        REQUIRE(status.ok());
        f.commit(x);
        const auto next = test::step<D>(x, 0.05, seed + 10);
        double smallest = std::numeric_limits<double>::infinity();
        for (std::size_t a = 0; a < x.size(); ++a)
        {
            typename GradF<D>::Scratch scratch;
            scratch.resize(f.ref.neighbours.count(a));
            const auto kin = scheme.kinematics(a, next, f.ref, false, scratch);
            Vec<D> moment = Vec<D>::Zero();
            for (std::size_t j = 0; j < f.ref.neighbours.count(a); ++j)
            {
                moment += scratch.w[j] * scratch.xr[j];
            }
            oneSided += moment.norm() > 0.1 ? 1 : 0;
            scheme.fillFramedSamples(a, next, f.ref.neighbours, kin, scratch);
            for (std::size_t j = 0; j < f.ref.neighbours.count(a); ++j)
            {
                smallest = std::min(smallest, scratch.F[j].determinant());
            }
        }
        CHECK(smallest > 0.0);
    }
    CHECK(oneSided > 0);
}

template <int D>
void forceIsTheGradient(const char* scheme, const char* material)
{
    INFO(D << "D " << scheme << " " << material);
    TotalLagrangian<D> f(scheme, material);
    const auto x1 = test::deformCurrent<D>(f.ref.x, 17);
    REQUIRE(f.commit(x1) > 0.0);
    const auto x2 = test::step<D>(x1, 0.02, 3);
    REQUIRE(f.commit(x2) > 0.0);
    test::checkForceIsTheGradient<D>(f, test::step<D>(x2, 0.02, 4));
}

} // namespace

TEST_CASE("gradF elasticState, total Lagrangian: the first step is the paper's, bit for bit "
          "(and affine motions after commits)",
          "[plasticity][gradF][frames]")
{
    test::loadModelLibraries();
    firstStepIsThePapers<2>(kFramed, "type gradF;", kPlastic);
    firstStepIsThePapers<3>(kFramed, "type gradF;", kPlastic);
    firstStepIsThePapers<2>(kFramed, "type gradF;", kDP);
}

TEST_CASE("gradF elasticState, total Lagrangian, fit joint: the first step is the paper's joint "
          "fit to round-off (G26.2)",
          "[plasticity][gradF][frames]")
{
    test::loadModelLibraries();
    firstJointStepIsThePapers<2>(kPlastic);
    firstJointStepIsThePapers<3>(kPlastic);
    firstJointStepIsThePapers<2>(kDP);
}

TEST_CASE("gradF elasticState, total Lagrangian: a frame move keeps Pi (G25, G4.1)",
          "[plasticity][gradF][frames]")
{
    test::loadModelLibraries();
    frameMoveKeepsTheEnergy<2>();
    frameMoveKeepsTheEnergy<3>();
}

TEST_CASE("gradF elasticState, total Lagrangian: force = -dPi/dx with moved frames, momentum "
          "conserved",
          "[plasticity][gradF][frames]")
{
    test::loadModelLibraries();
    forceIsTheGradient<2>(kFramed, kPlastic);
    forceIsTheGradient<3>(kFramed, kPlastic);
    forceIsTheGradient<2>(kFramed, kDP);
    forceIsTheGradient<2>(kFramedJoint, kPlastic);
    forceIsTheGradient<3>(kFramedJoint, kDP);
}

TEST_CASE("gradF elasticState, total Lagrangian: objective (a rotated, yielded configuration "
          "rotates the forces)",
          "[plasticity][gradF][frames]")
{
    test::loadModelLibraries();
    test::checkObjectiveAfterMoves<2>(kFramed, kPlastic, false);
    test::checkObjectiveAfterMoves<3>(kFramed, kPlastic, false);
    test::checkObjectiveAfterMoves<3>(kFramedJoint, kDP, false);
}

TEST_CASE("gradF elasticState, total Lagrangian: admissible samples on a distorted cloud and its "
          "one-sided edge",
          "[plasticity][gradF][frames]")
{
    test::loadModelLibraries();
    samplesAdmissible<2>(kFramed);
    samplesAdmissible<3>(kFramed);
    samplesAdmissible<2>(kFramedJoint);
    samplesAdmissible<3>(kFramedJoint);
}
