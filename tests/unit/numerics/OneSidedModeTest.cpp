// Mode response of the `oneSided` scheme (sphSolid's own extension, docs/theory/vidal-modes.md
// §V7): on an interior lattice each side's own F^j for the mode u_b = A c (-1)^{n·b} against
// the one-sided lattice sum (V7.2); opposite sides respond oppositely (V7.3), so the mean of the
// sides' f is blind and only the energy average sees the modes (V7.4); the checkerboard's
// response is of order one where no shift of the gradient reaches 0.014 (§V5); and a move of
// the reference keeps each side's deformation (the energy is continuous across it). The two
// sides of each comparison share only the kernel's dW/dr.
#include "numerics/NumericsSupport.hpp"
#include "stabilisation/oneSided/OneSided.hpp"

#include <iostream>

using namespace sph;

namespace
{

constexpr double kAmplitude = 0.25; // each f^j is linear in x: any amplitude gives the same r^j
constexpr int kSide = 21;           // the quintic at h = 2Δx reaches 6Δx: the centre is interior

const std::array<std::array<int, 2>, 3> kModes{{{1, 0}, {0, 1}, {1, 1}}};

double modeSign(const std::array<int, 2>& n, const Vec<2>& k)
{
    const long sum = n[0] * std::lround(k[0]) + n[1] * std::lround(k[1]);
    return sum % 2 == 0 ? 1.0 : -1.0;
}

std::size_t centre()
{
    return static_cast<std::size_t>(kSide / 2) * kSide + static_cast<std::size_t>(kSide / 2);
}

std::unique_ptr<test::SchemeFixture<2>> makeFixture(const std::string& kernel, double h,
                                                    bool updated = false)
{
    return std::make_unique<test::SchemeFixture<2>>(
        test::lattice<2>(kSide, 0.0, 1), "type oneSided;",
        "type linearElastic; E 1; nu 0.3; rho 1;", updated, h, kernel);
}

std::vector<Vec<2>> displaced(const std::vector<Vec<2>>& X, const std::array<int, 2>& n,
                              const Vec<2>& c)
{
    std::vector<Vec<2>> x = X;
    for (std::size_t b = 0; b < X.size(); ++b)
    {
        x[b] += kAmplitude * modeSign(n, X[b]) * c;
    }
    return x;
}

// Side j's response r^j from the scheme: δf^j_a = (A/Δx) (-1)^{n·a} c ⊗ r^j (checked rank one).
Vec<2> sideResponse(const test::SchemeFixture<2>& fixture, int j, const std::array<int, 2>& n,
                    const Vec<2>& c)
{
    const auto& scheme = dynamic_cast<const OneSided<2>&>(*fixture.scheme);
    const std::size_t a = centre();
    REQUIRE((fixture.X[a] - Vec<2>::Constant(kSide / 2)).norm() == 0.0);
    const auto x = displaced(fixture.X, n, c);
    const Mat<2> df = scheme.sideDeformationGradient(j, a, x, fixture.ref) - Mat<2>::Identity();
    const Vec<2> r = (modeSign(n, fixture.X[a]) / kAmplitude) * (df.transpose() * c);
    CHECK((df - kAmplitude * modeSign(n, fixture.X[a]) * c * r.transpose()).cwiseAbs().maxCoeff() <
          1e-13);
    return r;
}

// (V7.2): r^j = -2 (M^j)^{-T} Σ_{n·k odd} w^j(k) ∇W(-k Δx), M^j = Σ_k w^j(k) k ⊗ ∇W(-k Δx),
// w^j(k) = 1, ½, 0 as s k_i > 0, = 0, < 0 (unit spacing), written here from the kernel's dW/dr.
Vec<2> predictedResponse(const std::string& kernelName, double h, int j,
                         const std::array<int, 2>& n)
{
    const auto kernel = test::makeKernel(kernelName, 2, 1.0, h);
    const int reach = static_cast<int>(std::ceil(kernel->supportRadius())) + 1;
    Mat<2> M = Mat<2>::Zero();
    Vec<2> odd = Vec<2>::Zero();
    for (int i = -reach; i <= reach; ++i)
    {
        for (int l = -reach; l <= reach; ++l)
        {
            const Vec<2> k(i, l);
            const double r = k.norm();
            if (r == 0.0)
            {
                continue;
            }
            const double along = (j % 2 == 0 ? 1.0 : -1.0) * k[j / 2];
            const double w = along > 0.0 ? 1.0 : (along < 0.0 ? 0.0 : 0.5);
            const Vec<2> g = w * (kernel->dWdr(r) / r) * Vec<2>(-k);
            M += k * g.transpose();
            if (modeSign(n, k) < 0.0)
            {
                odd += g;
            }
        }
    }
    return -2.0 * M.transpose().inverse() * odd;
}

// The energy average's response (V7.4): R = sqrt((1/2D) Σ_j |r^j|²).
double averagedResponse(const test::SchemeFixture<2>& fixture, const std::array<int, 2>& n,
                        const Vec<2>& c)
{
    double sum = 0.0;
    for (int j = 0; j < OneSided<2>::sides; ++j)
    {
        sum += sideResponse(fixture, j, n, c).squaredNorm();
    }
    return std::sqrt(sum / OneSided<2>::sides);
}

} // namespace

TEST_CASE("oneSided: each side's 2D mode response is the one-sided lattice sum",
          "[oneSided][modes]")
{
    test::loadModelLibraries();
    const Vec<2> polarisation(0.6, 0.8);
    for (const std::string kernel : {"cubicSpline", "wendlandC2", "quinticSpline"})
    {
        for (const double h : {1.2, 1.3, 1.5, 2.0})
        {
            const auto fixture = makeFixture(kernel, h);
            for (const auto& n : kModes)
            {
                Mat<2> meanDf = Mat<2>::Zero();
                for (int j = 0; j < OneSided<2>::sides; ++j)
                {
                    const Vec<2> r = sideResponse(*fixture, j, n, polarisation);
                    const Vec<2> predicted = predictedResponse(kernel, h, j, n);
                    INFO(kernel << " h/dx = " << h << " side " << j << " n = (" << n[0] << ", "
                                << n[1] << ")");
                    CHECK((r - predicted).norm() <= 1e-12 * std::max(1.0, predicted.norm()));
                    // (V7.3): the opposite side responds oppositely.
                    if (j % 2 == 1)
                    {
                        CHECK((r + sideResponse(*fixture, j - 1, n, polarisation)).norm() < 1e-12);
                    }
                }
                // The plain mean of the sides' F (what a single F from Σ_j d^j would see, and
                // what the scheme writes out) is blind to every mode.
                const auto x = displaced(fixture->X, n, polarisation);
                meanDf = fixture->scheme->deformationGradient(centre(), x, fixture->ref) -
                         Mat<2>::Identity();
                CHECK(meanDf.cwiseAbs().maxCoeff() < 1e-12);
            }
        }
    }
}

TEST_CASE("oneSided sees the checkerboard and both sawtooths at every h/dx", "[oneSided][modes]")
{
    // §V7's table (cubic spline): R of the energy average, against ≤ 0.014 for any shift along
    // an axis (§V5) and 2 for a nearest-neighbour difference.
    test::loadModelLibraries();
    const std::array<double, 4> hs{1.2, 1.3, 1.5, 2.0};
    const std::array<double, 4> sawtooth{1.3696, 1.2464, 1.0579, 0.7152};
    const std::array<double, 4> checkerboard{1.0359, 0.9291, 0.8148, 0.6307};
    for (std::size_t i = 0; i < hs.size(); ++i)
    {
        const auto fixture = makeFixture("cubicSpline", hs[i]);
        for (const Vec<2>& c : {Vec<2>(1.0, 0.0), Vec<2>(0.0, 1.0)})
        {
            const double x = averagedResponse(*fixture, {1, 0}, c);
            const double y = averagedResponse(*fixture, {0, 1}, c);
            const double cb = averagedResponse(*fixture, {1, 1}, c);
            std::cout << "oneSided 2D cubic h/dx=" << hs[i] << " c=(" << c.transpose()
                      << "): sawtooth x " << x << ", y " << y << ", checkerboard " << cb << "\n";
            CHECK(x == Approx(sawtooth[i]).margin(5e-5));
            CHECK(y == Approx(sawtooth[i]).margin(5e-5));
            CHECK(cb == Approx(checkerboard[i]).margin(5e-5));
            CHECK(cb > 0.6);
        }
    }
    for (const std::string kernel : {"wendlandC2", "quinticSpline"})
    {
        for (const double h : hs)
        {
            const auto fixture = makeFixture(kernel, h);
            const Vec<2> c(1.0, 0.0);
            std::cout << "oneSided 2D " << kernel << " h/dx=" << h << ": sawtooth x "
                      << averagedResponse(*fixture, {1, 0}, c) << ", y "
                      << averagedResponse(*fixture, {0, 1}, c) << ", checkerboard "
                      << averagedResponse(*fixture, {1, 1}, c) << "\n";
            CHECK(averagedResponse(*fixture, {1, 1}, c) > 0.3);
        }
    }
}

TEST_CASE("oneSided keeps each side's deformation across a move of the reference",
          "[oneSided][modes]")
{
    // Updated Lagrangian: moving the reference to x must not change Π (each F^j = f^j G^j F^r
    // is what it was); with F^r alone (the mean of the sides) the modes' energy would be lost.
    test::loadModelLibraries();
    auto fixture = makeFixture("cubicSpline", 1.5); // x^r = the lattice, moved below
    const auto x = displaced(fixture->X, {1, 1}, Vec<2>(0.03, -0.02));
    const double before = fixture->energy(x);
    REQUIRE(before > 0.0);
    REQUIRE(fixture->moveReference(x).ok());
    const double after = fixture->energy(x);
    CHECK(after == Approx(before).epsilon(1e-12));
    // The mean F^r alone holds (almost) none of it: the checkerboard is invisible to the mean.
    double meanOnly = 0.0;
    for (std::size_t a = 0; a < x.size(); ++a)
    {
        Mat<2> P;
        double psi;
        fixture->material->evaluate(&fixture->ref.F[a], &P, &psi, 1, HistoryOf::particles(a));
        meanOnly += fixture->V0[a] * psi;
    }
    std::cout << "oneSided move: energy before " << before << ", after " << after
              << ", of the mean F^r alone " << meanOnly << "\n";
    CHECK(meanOnly < 0.5 * before);
    // A second displacement from the moved reference still sees the first one.
    const auto y = displaced(x, {1, 0}, Vec<2>(0.01, 0.0));
    CHECK(fixture->energy(y) > 0.0);
}
