// gradF's moment points in updated Lagrangian form with plastic history (`samplePoints moments;
// plasticSamples elasticState;`, docs/theory/gradF-moments.md §M7):
//   - the orthogonal polar factor (closed form in 2D, Newton in 3D) and the carried axes (M7.2):
//     they keep the rule's moments, and axes that already are the rule's are kept;
//   - the samples laid out per particle: each particle's states stay with it when the list
//     changes, a first layout starts from the particle's state, the restart field round-trips,
//     and a field written with other settings is refused;
//   - through moves in plastic flow the force is −∂Π/∂x with zero total, the scheme is objective
//     (with Cholesky axes at every move it is not: the points would stay while the material
//     turns), conserving weights keep Π at a move, and a move makes far less energy than the
//     neighbour samples' does (M7.3: none inside the body).
#include "numerics/PlasticMotion.hpp"
#include "numerics/SampleHistorySupport.hpp"
#include "stabilisation/gradF/GradF.hpp"
#include "stabilisation/gradF/MomentPoints.hpp"

#include <random>

using namespace sph;

namespace
{

const char* kMovingMoments = "type gradF; plasticSamples elasticState; samplePoints moments;";

template <int D>
Mat<D> randomMatrix(std::mt19937& random, double scale)
{
    std::normal_distribution<double> normal;
    Mat<D> X = Mat<D>::Identity();
    for (int i = 0; i < D; ++i)
    {
        for (int j = 0; j < D; ++j)
        {
            X(i, j) += scale * normal(random);
        }
    }
    return X;
}

// R orthogonal and Rᵀ X symmetric positive definite: the polar decomposition's factor.
template <int D>
void polarFactor()
{
    INFO(D << "D");
    std::mt19937 random(11);
    for (int trial = 0; trial < 200; ++trial)
    {
        Mat<D> X = randomMatrix<D>(random, trial < 100 ? 0.3 : 2.0);
        if (trial % 3 == 0)
        {
            X.row(0) *= -1.0; // a reflection's polar factor
        }
        const Mat<D> R = orthogonalPolarFactor<D>(X);
        const Mat<D> P = R.transpose() * X;
        CHECK((R.transpose() * R - Mat<D>::Identity()).norm() < 1e-14);
        CHECK((P - P.transpose()).norm() < 1e-13 * X.norm());
        CHECK(Eigen::SelfAdjointEigenSolver<Mat<D>>(0.5 * (P + P.transpose())).eigenvalues().minCoeff() > 0.0);
        CHECK(R.determinant() * X.determinant() > 0.0);
    }
}

// (M7.2): the carried axes have the rule's A Aᵀ = D Σ and are the closest such to the carried
// ones; axes that already have it are kept.
template <int D>
void carriedAxesKeepTheMoments()
{
    INFO(D << "D");
    std::mt19937 random(5);
    for (int trial = 0; trial < 50; ++trial)
    {
        // Some axes C of a rule (any C with C Cᵀ = D Σ; the Cholesky factor is one of them).
        const Mat<D> cholesky = randomMatrix<D>(random, 0.4);
        const Mat<D> spread = cholesky * cholesky.transpose();
        const Mat<D> carried = randomMatrix<D>(random, 0.4);
        const Mat<D> A = carriedAxes<D>(cholesky, carried);
        CHECK((A * A.transpose() - spread).norm() < 1e-13 * spread.norm());
        // Any other axes of the rule are further from `carried`.
        const Mat<D> U = orthogonalPolarFactor<D>(randomMatrix<D>(random, 0.5));
        CHECK((A - carried).norm() <= (cholesky * U - carried).norm() + 1e-14);
        // The rule's own axes, turned: chosen as they are.
        const Mat<D> own = cholesky * U;
        CHECK((carriedAxes<D>(cholesky, own) - own).norm() < 1e-13 * own.norm());
    }
}

// Fewer neighbours than points, padded with entries of weight 0 at the particle (as a particle
// that carries its states is, §M7): the points have the few neighbours' moments.
void fewNeighboursPadded()
{
    const std::vector<Vec<2>> xr{Vec<2>::Zero(), Vec<2>(1.0, 0.2), Vec<2>(-0.3, 0.9),
                                 Vec<2>::Zero(), Vec<2>::Zero()};
    const std::vector<double> w{0.5, 0.3, 0.2, 0.0, 0.0};
    CHECK_FALSE(momentPoints<2>(xr.data(), w.data(), 3, nullptr, nullptr)); // too few as they are
    Vec<2> points[5];
    double weights[5];
    REQUIRE(momentPoints<2>(xr.data(), w.data(), 5, points, weights));
    Vec<2> m = Vec<2>::Zero(), mq = Vec<2>::Zero();
    Mat<2> M = Mat<2>::Zero(), Mq = Mat<2>::Zero();
    double total = 0.0;
    for (int j = 0; j < 5; ++j)
    {
        m += w[j] * xr[j];
        M += w[j] * xr[j] * xr[j].transpose();
        CHECK(weights[j] >= 0.0);
        total += weights[j];
        mq += weights[j] * points[j];
        Mq += weights[j] * points[j] * points[j].transpose();
    }
    CHECK(total == Approx(1.0).epsilon(1e-15));
    CHECK((mq - m).norm() < 1e-15);
    CHECK((Mq - M).norm() < 1e-14);
    // The same points on carried axes (M7.2): momentAxes reads the axes back, and the turned
    // points keep every moment.
    const Mat<2> axes = momentAxes<2>(points);
    const Mat<2> turned = carriedAxes<2>(axes, Eigen::Rotation2Dd(0.4).toRotationMatrix() * axes);
    REQUIRE((turned - axes).norm() > 0.1 * axes.norm()); // they did turn
    turnMomentPoints<2>(points, turned);
    CHECK((momentAxes<2>(points) - turned).norm() < 1e-15);
    Vec<2> mt = Vec<2>::Zero();
    Mat<2> Mt = Mat<2>::Zero();
    for (int q = 0; q < 5; ++q)
    {
        mt += weights[q] * points[q];
        Mt += weights[q] * points[q] * points[q].transpose();
    }
    CHECK((mt - m).norm() < 1e-15);
    CHECK((Mt - M).norm() < 1e-14);
}

template <int D>
void laidOutPerParticle()
{
    INFO(D << "D");
    const std::size_t count = MomentPoints<D>::count;
    test::samples::Samples<D> s(3, count);
    const std::size_t stride = s.history.stride();
    CHECK(s.history.name() == "momentPointHistory");
    std::mt19937 random(7);
    std::vector<std::vector<double>> states(s.x.size());
    s.history.clearPending();
    for (std::size_t a = 0; a < s.x.size(); ++a)
    {
        REQUIRE(s.history.entries(a) == count);
        for (std::size_t q = 0; q < count; ++q)
        {
            const std::vector<double> state = test::samples::randomState<D>(random);
            states[a].insert(states[a].end(), state.begin(), state.end());
        }
        s.history.keepPending(s.history.begin(a), count, states[a].data());
    }
    s.history.commit();
    // A list of other lengths (a larger radius): every particle keeps its states, slot by slot.
    s.relist(s.x, 2.3);
    REQUIRE(s.list.count(0) != count);
    for (std::size_t a = 0; a < s.x.size(); ++a)
    {
        CHECK(test::samples::sameBits(s.read(a).data(), states[a].data(), count * stride));
    }
    // The restart field round-trips; entries of another layout are refused at the next layout.
    std::vector<double> values;
    std::vector<std::size_t> counts;
    for (std::size_t a = 0; a < s.x.size(); ++a)
    {
        std::vector<double> entry(s.history.entries(a) * s.history.width());
        s.history.get(a, entry.data());
        for (std::size_t q = 0; q < count; ++q)
        {
            CHECK(entry[q * s.history.width()] == static_cast<double>(q));
        }
        values.insert(values.end(), entry.begin(), entry.end());
        counts.push_back(s.history.entries(a));
    }
    s.history.assign(counts, values);
    s.history.follow(s.list, s.body, s.materials, nullptr);
    for (std::size_t a = 0; a < s.x.size(); ++a)
    {
        CHECK(test::samples::sameBits(s.read(a).data(), states[a].data(), count * stride));
    }
    counts[1] += 1;
    values.insert(values.end(), values.begin(), values.begin() + static_cast<long>(s.history.width()));
    s.history.assign(counts, values);
    CHECK_THROWS_AS(s.history.follow(s.list, s.body, s.materials, nullptr), std::runtime_error);
}

// A particle laid out for the first time: its samples start from its own state.
template <int D>
void firstLayoutFromTheParticle()
{
    INFO(D << "D");
    test::SchemeFixture<D> f(test::schemeCloud<D>(7), kMovingMoments, test::kPlastic, false,
                             test::schemeHOverDx<D>());
    const auto x = test::mapped<D>(test::affine<D>(0.12, 3), f.ref.x);
    REQUIRE(f.commit(x) > 0.0); // every sample at F_a: the same flow as the particle's own
    const double e1 = f.energy(x);
    // A scheme built afresh on the committed particle states: its samples start from them.
    auto fresh = test::build<Stabilisation<D>>(kMovingMoments, {f.kernel.get(), nullptr, true}, D);
    REQUIRE(fresh->prepare(f.ref).ok());
    ParticleFields<D> fields;
    fields.setSize(x.size());
    fresh->declareHistory(f.materials, fields);
    CHECK(fresh->energy(f.input(x)) == Approx(e1).epsilon(1e-12));
}

} // namespace

TEST_CASE("moment points: the orthogonal polar factor, and the carried axes keep the moments",
          "[gradF][moments]")
{
    polarFactor<2>();
    polarFactor<3>();
    carriedAxesKeepTheMoments<2>();
    carriedAxesKeepTheMoments<3>();
    fewNeighboursPadded();
}

TEST_CASE("moment points' samples laid out per particle: kept across lists, restart, refusal",
          "[gradF][moments][samples]")
{
    test::loadModelLibraries();
    laidOutPerParticle<2>();
    laidOutPerParticle<3>();
}

TEST_CASE("gradF moments, updated Lagrangian, plastic: force = -dPi/dx after moves, objective",
          "[gradF][moments][plasticity]")
{
    test::loadModelLibraries();
    for (const char* material : {test::kPlastic, test::kDP})
    {
        test::checkForceAfterMoves<2>(kMovingMoments, material);
        test::checkForceAfterMoves<3>(kMovingMoments, material);
        test::checkObjectiveAfterMoves<2>(kMovingMoments, material);
        test::checkObjectiveAfterMoves<3>(kMovingMoments, material);
    }
    firstLayoutFromTheParticle<2>();
    firstLayoutFromTheParticle<3>();
}

TEST_CASE("gradF moments, updated Lagrangian, plastic: the energy at moves (M7.3, G9.1)",
          "[gradF][moments][plasticity][moveWeights]")
{
    test::loadModelLibraries();
    for (const char* material : {test::kPlastic, test::kDP})
    {
        INFO(material);
        const double points = test::largestMoveChange<2>(kMovingMoments, material);
        const double pairs =
            test::largestMoveChange<2>("type gradF; plasticSamples elasticState;", material);
        INFO("moments " << points << ", neighbours " << pairs);
        CHECK(points < 0.2 * pairs);
        CHECK(test::largestMoveChange<2>(std::string(kMovingMoments) + " moveWeights conserving;",
                                   material) < 1e-12);
        CHECK(test::largestMoveChange<3>(std::string(kMovingMoments) + " moveWeights conserving;",
                                   material) < 1e-12);
    }
}
