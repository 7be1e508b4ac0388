// gradF's elasticState samples (docs/theory/gradF-plastic.md): the samples carry their elastic
// state across moves of the reference configuration instead of a carried gradient of F.
//   - (G4.1) a rebased state has the same be, stress and energy at its new gradient;
//   - (G4.2) a move changes Π only through the weights: every kept sample's energy is what it
//     was, a new pair starts from its neighbour's state;
//   - after a move, K = 0 for the particles with history, the force is −∂Π/∂x (finite
//     differences), momentum is conserved;
//   - objectivity: rotating every current configuration rotates the forces, changes no scalar;
//   - (§G9) moveWeights: with conserving weights a move changes Π by round-off only (pairs
//     entering and leaving included), with nonIncreasing it never raises it, and the force
//     between moves stays −∂Π/∂x.
// Against the paper's gradF (consistency, admissibility, elastic materials) and a move's frames:
// GradFElasticStateConsistencyTest.cpp.
#include "numerics/PlasticMotion.hpp"
#include "stabilisation/gradF/GradF.hpp"

#include <algorithm>
#include <cstring>
#include <map>

using namespace sph;
using sph::test::affine;
using sph::test::mapped;
using sph::test::kDP;
using sph::test::kElasticJ2;
using sph::test::kPlastic;

namespace
{

const char* kElasticState = "type gradF; plasticSamples elasticState;";

std::string moveWeights(const std::string& weights)
{
    return std::string(kElasticState) + " moveWeights " + weights + ";";
}

// W at F from one packed state (the samples' evaluation).
template <int D>
double sampleEnergy(const Material<D>& material, const Mat<D>& F, const std::vector<double>& state)
{
    Mat<D> P;
    double psi = 0.0;
    material.evaluate(&F, &P, &psi, 1, HistoryOf::samples(state.data(), state.size()));
    return psi;
}

template <int D>
Mat<D> sampleKirchhoff(const Material<D>& material, const Mat<D>& F, const std::vector<double>& state)
{
    Mat<D> P;
    material.evaluate(&F, &P, nullptr, 1, HistoryOf::samples(state.data(), state.size()));
    return P * F.transpose();
}

// (G4.1): after rebaseHistory(from → to) the state at `to` has the stress (τ) and energy the
// old one had at `from`, also where the point yields (the trial be is the same, so is the return).
template <int D>
void rebaseKeepsTheElasticState(const char* materialText)
{
    INFO(D << "D " << materialText);
    test::SchemeFixture<D> f(test::schemeCloud<D>(5), "type none;", materialText, false,
                             test::schemeHOverDx<D>());
    // A plastic history at particle 0: a commit at a large affine strain.
    REQUIRE(f.commit(mapped<D>(affine<D>(0.12, 3), f.ref.x)) > 0.0);
    std::vector<double> state(f.material->historyComponents());
    f.material->packHistory(0, state.data());
    for (const unsigned seed : {5u, 11u})
    {
        const Mat<D> from = affine<D>(0.15, seed);
        const Mat<D> to = affine<D>(0.2, seed + 1);
        std::vector<double> rebased = state;
        f.material->rebaseHistory(rebased.data(), from, to);
        const Mat<D> tauFrom = sampleKirchhoff<D>(*f.material, from, state);
        const Mat<D> tauTo = sampleKirchhoff<D>(*f.material, to, rebased);
        REQUIRE(tauFrom.norm() > 1e-3);
        CHECK((tauTo - tauFrom).norm() < 1e-12 * tauFrom.norm());
        const double W = sampleEnergy<D>(*f.material, from, state);
        CHECK(sampleEnergy<D>(*f.material, to, rebased) == Approx(W).epsilon(1e-12));
        // And it yields at both (a trial beyond the surface): the return is the same one.
        const Mat<D> further = affine<D>(0.35, seed + 2);
        std::vector<double> again = state;
        f.material->rebaseHistory(again.data(), further * from, further * to);
        CHECK((sampleKirchhoff<D>(*f.material, further * to, rebased) -
               sampleKirchhoff<D>(*f.material, further * from, state))
                  .norm() < 1e-10 * tauFrom.norm());
    }
    // A particle's samples rebased together (one to⁻¹ for all) are each rebased alone, bit for
    // bit: a move's result does not depend on how its samples are grouped.
    const std::size_t stride = state.size();
    const Mat<D> from[3] = {affine<D>(0.15, 5), affine<D>(0.1, 7), affine<D>(0.05, 9)};
    const Mat<D> to = affine<D>(0.2, 6);
    std::vector<double> together;
    for (int j = 0; j < 3; ++j)
    {
        together.insert(together.end(), state.begin(), state.end());
    }
    f.material->rebaseHistories(together.data(), stride, 3, from, to);
    for (std::size_t j = 0; j < 3; ++j)
    {
        std::vector<double> alone = state;
        f.material->rebaseHistory(alone.data(), from[j], to);
        CHECK(std::equal(alone.begin(), alone.end(),
                         together.begin() + static_cast<long>(j * stride)));
        CHECK(!std::equal(alone.begin(), alone.end(), state.begin()));
    }
}

// (G4.2): Π after a move = Σ_a V0_a Σ_b Ŵ'_ab W_ab with every kept sample's W as it was before
// the move and a new pair's W that of its neighbour's own state at the neighbour's F. The
// states are made uniform (a commit at an affine F, where every sample is F_a) so that the test
// can compute each sample's W from the particle's state.
template <int D>
void moveChangesOnlyTheWeights(const char* materialText)
{
    INFO(D << "D " << materialText);
    test::SchemeFixture<D> f(test::schemeCloud<D>(7), kElasticState, materialText, false,
                             test::schemeHOverDx<D>());
    auto& scheme = dynamic_cast<GradF<D>&>(*f.scheme);
    REQUIRE(f.commit(mapped<D>(affine<D>(0.12, 3), f.ref.x)) > 0.0);
    std::vector<double> s0(f.material->historyComponents());
    f.material->packHistory(0, s0.data());
    const auto x1 = test::deformCurrent<D>(f.ref.x, 29);
    f.forces(x1); // lays the states along the list, as the solver's last evaluation does
    const ReferenceConfiguration<D> old = f.ref;
    const auto weights = [](const ReferenceConfiguration<D>& ref, std::size_t a)
    {
        const NeighbourList& list = ref.neighbours;
        std::vector<double> w(list.count(a));
        double sum = 0.0;
        for (std::size_t k = list.begin(a); k < list.end(a); ++k)
        {
            w[k - list.begin(a)] = ref.kernelValues(a).W[k - list.begin(a)] * ref.V[list.indices[k]];
            sum += w[k - list.begin(a)];
        }
        for (double& value : w)
        {
            value /= sum;
        }
        return w;
    };
    std::vector<std::map<std::size_t, double>> W(x1.size());
    std::vector<Mat<D>> F(x1.size()); // each particle's F at x1
    double before = 0.0;
    for (std::size_t a = 0; a < x1.size(); ++a)
    {
        const auto kin = scheme.kinematics(a, x1, old);
        F[a] = kin.F;
        const std::vector<double> w = weights(old, a);
        for (std::size_t k = old.neighbours.begin(a); k < old.neighbours.end(a); ++k)
        {
            const std::size_t b = old.neighbours.indices[k];
            const Mat<D> Fb = kin.F + kin.G.contract(Vec<D>(old.x[b] - old.x[a]));
            W[a][b] = sampleEnergy<D>(*f.material, Fb, s0);
            before += f.V0[a] * w[k - old.neighbours.begin(a)] * W[a][b];
        }
    }
    REQUIRE(f.energy(x1) == Approx(before).epsilon(1e-12));
    REQUIRE(f.moveReference(x1).ok());
    double after = 0.0;
    std::size_t newPairs = 0;
    for (std::size_t a = 0; a < x1.size(); ++a)
    {
        const std::vector<double> w = weights(f.ref, a);
        for (std::size_t k = f.ref.neighbours.begin(a); k < f.ref.neighbours.end(a); ++k)
        {
            const std::size_t b = f.ref.neighbours.indices[k];
            const auto kept = W[a].find(b);
            newPairs += kept == W[a].end() ? 1 : 0;
            const double Wab = kept != W[a].end() ? kept->second
                                                  : sampleEnergy<D>(*f.material, F[b], s0);
            after += f.V0[a] * w[k - f.ref.neighbours.begin(a)] * Wab;
        }
    }
    CHECK(newPairs > 0); // the list changed: new pairs were started
    CHECK(std::abs(after - before) > 1e-6 * before); // the weights changed: the check has teeth
    CHECK(f.energy(x1) == Approx(after).epsilon(1e-10));
    // The new reference gradient is the dilation J^(1/D) I (§G4).
    for (std::size_t a = 0; a < x1.size(); ++a)
    {
        const double J = F[a].determinant();
        CHECK((f.ref.F[a] - std::pow(J, 1.0 / D) * Mat<D>::Identity()).norm() < 1e-14 * std::abs(J));
    }
}

} // namespace

TEST_CASE("gradF elasticState: moveWeights conserving keeps Pi at every move, nonIncreasing "
          "never raises it (G9.1)",
          "[plasticity][gradF][moveWeights]")
{
    test::loadModelLibraries();
    for (const char* material : {kPlastic, kDP})
    {
        // Kernel weights: the moves change Π (the check below has teeth).
        CHECK(test::largestMoveChange<2>(moveWeights("kernel"), material) > 1e-6);
        CHECK(test::largestMoveChange<2>(moveWeights("conserving"), material) < 1e-12);
        CHECK(test::largestMoveChange<3>(moveWeights("conserving"), material) < 1e-12);
        bool neverRaises = true;
        test::largestMoveChange<2>(moveWeights("nonIncreasing"), material, &neverRaises);
        test::largestMoveChange<3>(moveWeights("nonIncreasing"), material, &neverRaises);
        CHECK(neverRaises);
    }
}

TEST_CASE("gradF elasticState: a rebased sample state keeps its elastic state (G4.1)",
          "[plasticity][gradF]")
{
    test::loadModelLibraries();
    rebaseKeepsTheElasticState<2>(kPlastic);
    rebaseKeepsTheElasticState<3>(kPlastic);
    rebaseKeepsTheElasticState<2>(kDP);
    rebaseKeepsTheElasticState<3>(kDP);
}

TEST_CASE("gradF elasticState: a reference move changes Pi only through the weights (G4.2)",
          "[plasticity][gradF]")
{
    test::loadModelLibraries();
    moveChangesOnlyTheWeights<2>(kPlastic);
    moveChangesOnlyTheWeights<3>(kPlastic);
    moveChangesOnlyTheWeights<2>(kDP);
}

TEST_CASE("gradF elasticState: after moves K = 0, force = -dPi/dx, momentum conserved",
          "[plasticity][gradF]")
{
    test::loadModelLibraries();
    test::checkForceAfterMoves<2>(kElasticState, kPlastic);
    test::checkForceAfterMoves<3>(kElasticState, kPlastic);
    test::checkForceAfterMoves<2>(kElasticState, kDP);
}

TEST_CASE("gradF elasticState: objective (a rotated, yielded configuration rotates the forces)",
          "[plasticity][gradF]")
{
    test::loadModelLibraries();
    test::checkObjectiveAfterMoves<2>(kElasticState, kPlastic);
    test::checkObjectiveAfterMoves<3>(kElasticState, kPlastic);
}
