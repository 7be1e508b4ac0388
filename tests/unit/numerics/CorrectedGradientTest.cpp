// Bonet-Lok corrected gradient (spec §2): reproducing conditions to round-off and exact F for
// affine maps on perturbed clouds in 1D/2D/3D, boundary particles included.
#include "numerics/NumericsSupport.hpp"
#include "particles/Parallel.hpp"

#include <omp.h>

using namespace sph;

namespace
{

template <int D>
void checkCorrectedGradient(int n, double perturbation)
{
    const auto X = test::lattice<D>(n, perturbation, 7);
    const auto kernel = test::makeKernel("cubicSpline", D, 1.0, 1.5);
    ReferenceConfiguration<D> ref;
    ParticleSet<D> particles;
    particles.resize(X.size());
    particles.X = X;
    for (std::size_t a = 0; a < X.size(); ++a)
    {
        particles.V0[a] = 1.0 + 0.2 * std::sin(1.7 * a); // unequal volumes
    }
    ref.setInitial(particles, false);
    REQUIRE(ref.rebuild(*kernel, particles.body, kernel->supportRadius()) < 0);

    // Σ_b g_a(b) = 0 and Σ_b x_b ⊗ g_a(b) = I.
    double sumError = 0.0;
    double identityError = 0.0;
    for (std::size_t a = 0; a < X.size(); ++a)
    {
        Vec<D> sum = ref.gSelf(a);
        Mat<D> moment = X[a] * ref.gSelf(a).transpose();
        for (std::size_t k = ref.neighbours.begin(a) + 1; k < ref.neighbours.end(a); ++k)
        {
            const Vec<D> g = ref.g(a, k);
            sum += g;
            moment += X[ref.neighbours.indices[k]] * g.transpose();
        }
        sumError = std::max(sumError, sum.cwiseAbs().maxCoeff());
        identityError = std::max(identityError, (moment - Mat<D>::Identity()).cwiseAbs().maxCoeff());
    }
    INFO(D << "D, " << X.size() << " particles");
    CHECK(sumError < 1e-12);
    CHECK(identityError < 1e-12);

    // F is exact for an affine map x = A X + c at every particle, boundary included.
    Mat<D> A = Mat<D>::Identity();
    for (int i = 0; i < D; ++i)
    {
        for (int j = 0; j < D; ++j)
        {
            A(i, j) += 0.3 * std::sin(1.0 + 3 * i + j);
        }
    }
    const Vec<D> c = Vec<D>::Constant(0.7);
    double affineError = 0.0;
    for (std::size_t a = 0; a < X.size(); ++a)
    {
        Mat<D> F = (A * X[a] + c) * ref.gSelf(a).transpose();
        for (std::size_t k = ref.neighbours.begin(a) + 1; k < ref.neighbours.end(a); ++k)
        {
            F += (A * X[ref.neighbours.indices[k]] + c) * ref.g(a, k).transpose();
        }
        affineError = std::max(affineError, (F - A).cwiseAbs().maxCoeff());
    }
    CHECK(affineError < 1e-12);
}

} // namespace

TEST_CASE("corrected gradient reproduces constants and linears (1D)", "[gradient]")
{
    checkCorrectedGradient<1>(20, 0.2);
}

TEST_CASE("corrected gradient reproduces constants and linears (2D)", "[gradient]")
{
    checkCorrectedGradient<2>(10, 0.2);
}

TEST_CASE("corrected gradient reproduces constants and linears (3D)", "[gradient]")
{
    checkCorrectedGradient<3>(5, 0.15);
}

TEST_CASE("a particle without enough neighbours is reported", "[gradient]")
{
    // Three particles on a line in 2D: M_a is singular.
    const auto kernel = test::makeKernel("cubicSpline", 2, 1.0, 1.5);
    ParticleSet<2> particles;
    particles.resize(3);
    particles.X = {Vec<2>(0, 0), Vec<2>(1, 0), Vec<2>(2, 0)};
    particles.V0 = {1, 1, 1};
    ReferenceConfiguration<2> ref;
    ref.setInitial(particles, false);
    CHECK(ref.rebuild(*kernel, particles.body, kernel->supportRadius()) == 0);
}

TEST_CASE("neighbour lists: self first, sorted, symmetric, same body only", "[neighbours]")
{
    auto points = test::lattice<2>(12, 0.3, 3);
    std::vector<int> body(points.size(), 0);
    for (std::size_t i = points.size() / 2; i < points.size(); ++i)
    {
        body[i] = 1;
    }
    const double radius = 2.1;
    const NeighbourList list = buildNeighbourList<2>(points, body, radius);
    for (std::size_t a = 0; a < points.size(); ++a)
    {
        REQUIRE(list.indices[list.begin(a)] == a);
        std::size_t expected = 0;
        for (std::size_t b = 0; b < points.size(); ++b)
        {
            if (b != a && body[a] == body[b] && (points[a] - points[b]).norm() < radius)
            {
                ++expected;
            }
        }
        CHECK(list.count(a) == expected + 1);
        for (std::size_t k = list.begin(a) + 2; k < list.end(a); ++k)
        {
            CHECK(list.indices[k - 1] < list.indices[k]);
        }
    }
    const NeighbourList cross = buildCrossNeighbourList<2>(points, points, radius);
    CHECK(cross.pairCount() > list.pairCount());
}

TEST_CASE("filtered candidate lists equal a fresh search", "[neighbours]")
{
    auto points = test::lattice<2>(15, 0.3, 8);
    const std::vector<int> body(points.size(), 0);
    const NeighbourList candidates = buildNeighbourList<2>(points, body, 2.2);
    for (auto& p : points)
    {
        p += Vec<2>(0.04 * std::sin(7 * p[1]), 0.04 * std::cos(5 * p[0])); // less than half the skin
    }
    const NeighbourList fresh = buildNeighbourList<2>(points, body, 2.0);
    const NeighbourList filtered = filterNeighbourList<2>(candidates, points, 2.0);
    CHECK(filtered.offsets == fresh.offsets);
    CHECK(filtered.indices == fresh.indices);
}

TEST_CASE("filtering in place gives a fresh search's lists for any thread count, into a reused list",
          "[neighbours]")
{
    // Enough points for the threads to split them (particles/Parallel.hpp), and a skin that
    // drops many candidates, so each block's pairs move down when the gaps are closed.
    auto points = test::lattice<2>(60, 0.3, 8);
    REQUIRE(points.size() > 3 * minimumParticlesForThreads);
    const std::vector<int> body(points.size(), 0);
    const NeighbourList candidates = buildNeighbourList<2>(points, body, 3.0);
    for (auto& p : points)
    {
        p += Vec<2>(0.04 * std::sin(7 * p[1]), 0.04 * std::cos(5 * p[0]));
    }
    const NeighbourList fresh = buildNeighbourList<2>(points, body, 2.0);
    REQUIRE(fresh.pairCount() < candidates.pairCount() * 3 / 4);
    const int threadsBefore = omp_get_max_threads();
    NeighbourList into = filterNeighbourList<2>(candidates, points, 2.5); // a longer list first
    for (const int threads : {1, 2, 3, 4})
    {
        omp_set_num_threads(threads);
        std::fill(into.indices.begin(), into.indices.end(), 0u); // no earlier result to find
        filterNeighbourList<2>(candidates, points, 2.0, into);
        INFO(threads << " threads");
        CHECK(into.offsets == fresh.offsets);
        CHECK(into.indices == fresh.indices);
    }
    omp_set_num_threads(threadsBefore);
}
