// gradF's elasticState samples against the paper's gradF (docs/theory/gradF-plastic.md §G3),
// and what a move hands over (GradFPlasticTest.cpp: the moves' energy, force and objectivity):
//   - the paper's gradF: identical for an affine motion, and for a smooth one the difference
//     falls with the spacing at second order;
//   - admissibility: every sample at a step's motion from a moved reference has det f > 0, on a
//     distorted cloud with one-sided (boundary) neighbourhoods;
//   - a failed run's hint never names the scheme in use;
//   - an elastic material gives the paper's gradF bit for bit;
//   - a move's frames are those referenceUpdate computes itself.
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

// Forces of ownHistory (the paper's kinematics, K carried) and elasticState after the same
// moves, relative to the largest force, over the particles at least `margin` from the cloud's
// edge.
template <int D>
double differenceFromPaper(const std::vector<Vec<D>>& cloud, const std::vector<std::vector<Vec<D>>>& path,
                           double hOverDx, double margin, double spacing)
{
    const auto forcesAfter = [&](const char* schemeText)
    {
        test::SchemeFixture<D> f(cloud, schemeText, kElasticJ2, false, hOverDx);
        f.kernel = test::makeKernel("cubicSpline", D, spacing, hOverDx);
        f.ref.rebuild(*f.kernel, f.body, f.scheme->referenceNeeds(*f.kernel).searchRadius);
        REQUIRE(f.scheme->prepare(f.ref).ok());
        for (std::size_t i = 0; i + 1 < path.size(); ++i)
        {
            f.forces(path[i]);
            REQUIRE(f.moveReference(path[i]).ok());
        }
        return f.forces(path.back());
    };
    const auto paper = forcesAfter("type gradF;");
    const auto ours = forcesAfter(kElasticState);
    Vec<D> lo = cloud[0], hi = cloud[0];
    for (const auto& p : cloud)
    {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    double difference = 0.0, scale = 0.0;
    for (std::size_t a = 0; a < cloud.size(); ++a)
    {
        if (((cloud[a] - lo).minCoeff() < margin) || ((hi - cloud[a]).minCoeff() < margin))
        {
            continue;
        }
        difference = std::max(difference, (ours[a] - paper[a]).norm());
        scale = std::max(scale, paper[a].norm());
    }
    REQUIRE(scale > 0.0);
    return difference / scale;
}

} // namespace
// Affine: every sample is F_a in both schemes, moves included (round-off). Smooth: the same
// quadratic motion on a cloud of spacing 1 and 1/2 over the same square; the difference falls
// at second order with the spacing (theory §G3).
TEST_CASE("gradF elasticState: the paper's gradF for affine motion, and to second order for "
          "smooth motion",
          "[plasticity][gradF]")
{
    test::loadModelLibraries();
    const auto cloud = test::lattice<2>(7, 0.2, 5);
    std::vector<std::vector<Vec<2>>> path;
    for (const double s : {0.03, 0.06, 0.08})
    {
        path.push_back(mapped<2>(affine<2>(s, 2), cloud));
    }
    CHECK(differenceFromPaper<2>(cloud, path, 1.4, -1.0, 1.0) < 1e-10);

    std::vector<double> differences;
    for (const int refine : {1, 2})
    {
        const double spacing = 1.0 / refine;
        auto fine = test::lattice<2>(12 * refine + 1, 0.1, 7);
        for (auto& p : fine)
        {
            p *= spacing;
        }
        const auto quadratic = [&](double s)
        {
            std::vector<Vec<2>> x(fine.size());
            for (std::size_t a = 0; a < fine.size(); ++a)
            {
                const Vec<2> X = fine[a];
                x[a] = X + s * Vec<2>(0.02 * X[0] * X[0] + 0.01 * X[0] * X[1], -0.015 * X[1] * X[1]);
            }
            return x;
        };
        std::vector<std::vector<Vec<2>>> smooth;
        for (const double s : {0.5, 1.0, 1.5})
        {
            smooth.push_back(quadratic(s));
        }
        differences.push_back(differenceFromPaper<2>(fine, smooth, 1.4, 3.0, spacing));
    }
    INFO("relative force difference at spacing 1 and 1/2: " << differences[0] << ", "
                                                            << differences[1]);
    CHECK(differences[0] < 0.05);
    CHECK(differences[1] < differences[0] / 3.0);
}

// Every sample F_b(a) = F_a + G_a x^r_ba at a step's motion from a moved reference has
// det > 0, on a cloud distorted by a large, rough motion (a random part of 0.05 spacings per
// step), boundary particles (one-sided neighbourhoods) included. The paper's kinematics, whose
// K carries the gradient of that rough motion from move to move, is measured alongside.
template <int D>
double smallestSampleDeterminant(const char* schemeText, int moves)
{
    test::SchemeFixture<D> f(test::schemeCloud<D>(7), schemeText, kPlastic, false,
                             test::schemeHOverDx<D>());
    auto& scheme = dynamic_cast<GradF<D>&>(*f.scheme);
    auto x = test::deformCurrent<D>(f.ref.x, 17);
    for (int s = 0; s < moves; ++s)
    {
        f.commit(x);
        if (!f.moveReference(x).ok())
        {
            return -1.0; // a particle inverted at the move
        }
        x = test::step<D>(x, 0.05, 10 + static_cast<unsigned>(s));
    }
    double smallest = 1e300;
    for (std::size_t a = 0; a < x.size(); ++a)
    {
        const auto kin = scheme.kinematics(a, x, f.ref);
        for (std::size_t k = f.ref.neighbours.begin(a); k < f.ref.neighbours.end(a); ++k)
        {
            const std::size_t b = f.ref.neighbours.indices[k];
            const Mat<D> sample = kin.F + kin.G.contract(Vec<D>(f.ref.x[b] - f.ref.x[a]));
            smallest = std::min(smallest, sample.determinant() / kin.F.determinant());
        }
    }
    return smallest;
}

TEST_CASE("gradF elasticState: admissible samples on distorted and one-sided neighbourhoods",
          "[plasticity][gradF]")
{
    test::loadModelLibraries();
    for (const int moves : {4, 12})
    {
        const double ours = smallestSampleDeterminant<2>(kElasticState, moves);
        const double paper = smallestSampleDeterminant<2>("type gradF;", moves);
        INFO(moves << " moves: smallest det F_b(a) / det F_a, elasticState " << ours
                   << ", the paper's kinematics " << paper);
        CHECK(ours > 0.0);
        if (moves == 12)
        {
            CHECK(paper < 0.0); // the failure of §G1: the check can tell the two apart
        }
    }
    CHECK(smallestSampleDeterminant<3>(kElasticState, 4) > 0.0);
}

// The solver's diagnosis of a failed run names what to try next given the scheme that failed:
// never the scheme itself.
TEST_CASE("a failed run's hint never suggests the scheme in use", "[gradF][failure]")
{
    test::loadModelLibraries();
    const auto kernel = test::makeKernel("cubicSpline", 2, 1.0, 1.4);
    const auto hint = [&](const std::string& text, bool updated, bool plastic)
    { return test::build<Stabilisation<2>>(text, {kernel.get()}, 2)->nextToTry(updated, plastic); };
    CHECK(hint("type none;", true, true).find("stabilisation gradF") != std::string::npos);
    CHECK(hint("type none;", false, false).find("stabilisation gradF") != std::string::npos);
    for (const bool plastic : {false, true})
    {
        for (const bool updated : {false, true})
        {
            CHECK(hint("type gradF;", updated, plastic).find("stabilisation gradF") ==
                  std::string::npos);
            CHECK(hint(kElasticState, updated, plastic).find("elasticState") == std::string::npos);
        }
    }
    CHECK(hint("type gradF;", true, true).find("plasticSamples elasticState") != std::string::npos);
    CHECK(hint("type gradF;", true, false).find("totalLagrangian") != std::string::npos);
    CHECK(hint("type gradF;", false, true).empty()); // TL gradF: no scheme to switch to
}

// The paper's elastic scheme is untouched: with an elastic material (no history) elasticState
// carries K and F^r as the paper's gradF does, through moves, bit for bit.
TEST_CASE("gradF elasticState: an elastic material gives the paper's gradF bit for bit",
          "[gradF]")
{
    test::loadModelLibraries();
    const char* elastic = "type neoHookean; mu 1; kappa 5; rho 1;";
    std::vector<std::vector<Vec<2>>> T;
    for (const char* scheme : {"type gradF;", kElasticState})
    {
        test::SchemeFixture<2> f(test::schemeCloud<2>(7), scheme, elastic, false, 1.4);
        auto x = test::deformCurrent<2>(f.ref.x, 17);
        for (unsigned s = 0; s < 3; ++s)
        {
            f.forces(x);
            REQUIRE(f.moveReference(x).ok());
            x = test::step<2>(x, 0.02, 20 + s);
        }
        T.push_back(f.forces(x));
        double K = 0.0;
        for (const auto& k : f.ref.K)
        {
            K = std::max(K, k.slice[0].norm() + k.slice[1].norm());
        }
        CHECK(K > 0.0); // K is carried
    }
    CHECK(T[0] == T[1]);
}

// A move (moveHistory, then referenceUpdate at the same positions) hands the frames J^(1/D) I it
// computed to referenceUpdate instead of computing the kinematics again: the same F^r, bit for
// bit, as a referenceUpdate of its own at those positions; and positions other than the move's
// are not given the move's frames.
TEST_CASE("gradF elasticState: a move's frames are those referenceUpdate computes itself",
          "[plasticity][gradF]")
{
    test::loadModelLibraries();
    test::SchemeFixture<2> f(test::schemeCloud<2>(7), kElasticState, kPlastic, false,
                             test::schemeHOverDx<2>());
    const auto x1 = test::deformCurrent<2>(f.ref.x, 17);
    REQUIRE(f.commit(x1) > 0.0);
    // Its own: at a copy of the move's positions (not the vector the move was given).
    f.scheme->moveHistory(x1, f.ref, f.body, {f.material.get()});
    const std::vector<Vec<2>> copy = x1;
    std::vector<Mat<2>> own;
    REQUIRE(f.scheme->referenceUpdate(copy, f.ref, own, nullptr).ok());
    std::vector<Mat<2>> handed;
    f.scheme->moveHistory(x1, f.ref, f.body, {f.material.get()});
    REQUIRE(f.scheme->referenceUpdate(x1, f.ref, handed, nullptr).ok());
    REQUIRE(handed.size() == own.size());
    std::size_t frames = 0;
    for (std::size_t a = 0; a < own.size(); ++a)
    {
        CHECK(std::memcmp(own[a].data(), handed[a].data(), sizeof(Mat<2>)) == 0);
        frames += handed[a](0, 1) == 0.0 && handed[a](0, 0) == handed[a](1, 1) ? 1 : 0;
    }
    CHECK(frames == own.size()); // every particle's is a dilation
    // Other positions after the move: computed there, not the move's.
    const auto x2 = test::step<2>(x1, 0.05, 3);
    f.scheme->moveHistory(x1, f.ref, f.body, {f.material.get()});
    std::vector<Mat<2>> elsewhere;
    REQUIRE(f.scheme->referenceUpdate(x2, f.ref, elsewhere, nullptr).ok());
    std::vector<Mat<2>> ownElsewhere;
    REQUIRE(f.scheme->referenceUpdate(x2, f.ref, ownElsewhere, nullptr).ok());
    for (std::size_t a = 0; a < own.size(); ++a)
    {
        CHECK(std::memcmp(ownElsewhere[a].data(), elsewhere[a].data(), sizeof(Mat<2>)) == 0);
    }
}
