// Mode response of the `vidal` scheme's shifted corrected gradient (docs/theory/vidal-modes.md,
// issue 34): on an interior lattice the scheme's own f_a for the mode u_b = A c (-1)^{n·b}
// against the lattice sum (V2.4), the first-order slope (V3.2), the cubic's exact linear law
// and blind band (V3.3)-(V3.5), the exact form at h = 1.5Δx (V3.6), the vanishing at h = 2Δx
// (V4.3) and the 2D statement of §V5. The two sides share only the kernel's dW/dr; a wrong
// sign, factor or shift direction in the derivation fails here.
#include "numerics/NumericsSupport.hpp"

#include <iostream>

using namespace sph;

namespace
{

constexpr double kAmplitude = 0.25; // f is linear in x: any amplitude gives the same response

template <int D>
std::string vidalText(const Vec<D>& beta)
{
    std::string text = "type vidal; beta (";
    for (int d = 0; d < D; ++d)
    {
        text += (d ? " " : "") + formatNumber(beta[d], 17);
    }
    return text + ");";
}

template <int D>
int coordinate(const Vec<D>& p, int d)
{
    return static_cast<int>(std::lround(p[d]));
}

// (-1)^{n·k}
template <int D>
double modeSign(const std::array<int, D>& n, const Vec<D>& k)
{
    int sum = 0;
    for (int d = 0; d < D; ++d)
    {
        sum += n[static_cast<std::size_t>(d)] * coordinate<D>(k, d);
    }
    return sum % 2 == 0 ? 1.0 : -1.0;
}

// The scheme's response r (V2.3): δf_a = (A/Δx) (-1)^{n·a} c ⊗ r at the centre particle of a
// unit lattice, from Vidal's deformationGradient. Also checks that δf_a is that rank-one matrix.
template <int D>
Vec<D> schemeResponse(const std::string& kernelName, double hOverDx, const Vec<D>& beta,
                      const std::array<int, D>& n, const Vec<D>& c)
{
    const int side = D == 1 ? 41 : 21; // the quintic at h = 2Δx reaches 6.6Δx: all interior
    const auto X = test::lattice<D>(side, 0.0, 1);
    const std::string material =
        D == 1 ? "type linearElastic; E 1; rho 1;" : "type linearElastic; E 1; nu 0.3; rho 1;";
    test::SchemeFixture<D> fixture(X, vidalText<D>(beta), material, false, hOverDx, kernelName);
    std::size_t a = 0;
    for (int d = D - 1; d >= 0; --d)
    {
        a = a * static_cast<std::size_t>(side) + static_cast<std::size_t>(side / 2);
    }
    REQUIRE((X[a] - Vec<D>::Constant(side / 2)).norm() == 0.0);
    std::vector<Vec<D>> x = X;
    for (std::size_t b = 0; b < X.size(); ++b)
    {
        x[b] += kAmplitude * modeSign<D>(n, X[b]) * c;
    }
    const Mat<D> df = fixture.scheme->deformationGradient(a, x, fixture.ref) - Mat<D>::Identity();
    const Vec<D> r = (modeSign<D>(n, X[a]) / kAmplitude) * (df.transpose() * c) / c.squaredNorm();
    CHECK((df - kAmplitude * modeSign<D>(n, X[a]) * c * r.transpose()).cwiseAbs().maxCoeff() <
          1e-13);
    return r;
}

// ∇W at v (the gradient of W(|v|) with respect to v).
template <int D>
Vec<D> gradW(const Kernel& kernel, const Vec<D>& v)
{
    const double r = v.norm();
    return r > 0.0 ? Vec<D>((kernel.dWdr(r) / r) * v) : Vec<D>::Zero();
}

// The lattice sums of the derivation, unit spacing: M(p) (V2.2) and ∇Φ_n(p) (V2.5).
template <int D>
struct LatticeSums
{
    Mat<D> M = Mat<D>::Zero();
    Vec<D> gradPhi = Vec<D>::Zero();
};

template <int D>
LatticeSums<D> latticeSums(const Kernel& kernel, const Vec<D>& p, const std::array<int, D>& n)
{
    const int reach = static_cast<int>(std::ceil(kernel.supportRadius() + p.norm())) + 1;
    LatticeSums<D> sums;
    std::array<int, D> index;
    index.fill(-reach);
    while (true)
    {
        Vec<D> k;
        for (int d = 0; d < D; ++d)
        {
            k[d] = index[static_cast<std::size_t>(d)];
        }
        const Vec<D> g = gradW<D>(kernel, Vec<D>(p - k));
        sums.M += k * g.transpose();
        if (modeSign<D>(n, k) < 0.0)
        {
            sums.gradPhi += g;
        }
        int d = 0;
        while (d < D && index[static_cast<std::size_t>(d)] == reach)
        {
            index[static_cast<std::size_t>(d)] = -reach;
            ++d;
        }
        if (d == D)
        {
            break;
        }
        ++index[static_cast<std::size_t>(d)];
    }
    return sums;
}

// The closed form (V2.4): r = -2 Δx^{D+1} M(hβ)^{-T} ∇Φ_n(hβ), Δx = 1.
template <int D>
Vec<D> predictedResponse(const std::string& kernelName, double hOverDx, const Vec<D>& beta,
                         const std::array<int, D>& n)
{
    const auto kernel = test::makeKernel(kernelName, D, 1.0, hOverDx);
    const LatticeSums<D> sums = latticeSums<D>(*kernel, Vec<D>(kernel->h() * beta), n);
    return -2.0 * sums.M.transpose().inverse() * sums.gradPhi;
}

// Second derivative of the cubic spline in 1D, written out (σ₁ = 2/3): independent of the
// kernel code for (V3.3)-(V3.5).
double cubicSecondDerivative(double r, double h)
{
    const double q = r / h;
    const double w2 = q < 1.0 ? -3.0 + 4.5 * q : (q < 2.0 ? 1.5 * (2.0 - q) : 0.0);
    return (2.0 / 3.0) / (h * h * h) * w2;
}

} // namespace

TEST_CASE("vidal's 1D sawtooth response is the lattice sum of the derivation", "[vidal][modes]")
{
    const std::array<int, 1> sawtooth{1};
    for (const std::string kernel : {"cubicSpline", "wendlandC2", "quinticSpline"})
    {
        for (const double h : {1.2, 1.3, 1.5, 2.0})
        {
            for (const double beta : {-0.3, 0.05, 0.1, 0.2, 0.3, 0.5})
            {
                const Vec<1> b(beta);
                const double r = schemeResponse<1>(kernel, h, b, sawtooth, Vec<1>(1.0))[0];
                const double predicted = predictedResponse<1>(kernel, h, b, sawtooth)[0];
                INFO(kernel << " h/dx = " << h << " beta = " << beta);
                CHECK(std::abs(r - predicted) <= 1e-12 * std::max(1.0, std::abs(predicted)));
            }
        }
    }
}

TEST_CASE("vidal at h = 1.5dx: the sawtooth response is -18 beta|beta|/(40 + 9 beta^2)",
          "[vidal][modes]")
{
    const std::array<int, 1> sawtooth{1};
    // (V3.6): r = -18 β|β| / (40 + 9β²) for |β| ≤ 1/3 (the k = ±1 pair cancels, only the
    // support edge at k = 3 acts; M = 80/81 + 2β²/9).
    for (const double beta : {-0.3, -0.1, 0.02, 0.1, 0.2, 0.3, 1.0 / 3.0})
    {
        const double r =
            schemeResponse<1>("cubicSpline", 1.5, Vec<1>(beta), sawtooth, Vec<1>(1.0))[0];
        INFO("beta = " << beta);
        CHECK(std::abs(r - (-18.0 * beta * std::abs(beta) / (40.0 + 9.0 * beta * beta))) < 1e-13);
    }
    // The values issue 34 quotes (against 2 for a nearest-neighbour difference).
    const auto response = [&](double h, double beta) {
        return std::abs(
            schemeResponse<1>("cubicSpline", h, Vec<1>(beta), sawtooth, Vec<1>(1.0))[0]);
    };
    std::cout << "vidal 1D sawtooth, cubic: h/dx=1.5 " << response(1.5, 0.1) << " (beta 0.1) "
              << response(1.5, 0.3) << " (beta 0.3); h/dx=1.2 " << response(1.2, 0.1) << ", "
              << response(1.2, 0.3) << "; h/dx=2 " << response(2.0, 0.3) << "\n";
    CHECK(response(1.5, 0.1) == Approx(0.0045).margin(0.00005));
    CHECK(response(1.5, 0.3) == Approx(0.040).margin(0.0005));
    CHECK(response(1.2, 0.1) == Approx(0.14).margin(0.005));
    CHECK(response(1.2, 0.3) == Approx(0.37).margin(0.005));
}

TEST_CASE("vidal's first-order sawtooth response is proportional to the odd sum of W''",
          "[vidal][modes]")
{
    // (V3.2): r = -2 hβ Δx² Σ_{k odd} W''(|k|Δx) / M(0) + O(β²); checked as r/β at small β,
    // W'' by central differences of the kernel's dW/dr.
    const std::array<int, 1> sawtooth{1};
    const double beta = 1e-5;
    for (const std::string name : {"cubicSpline", "wendlandC2", "quinticSpline"})
    {
        for (const double h : {1.2, 1.3, 1.5, 1.8})
        {
            const auto kernel = test::makeKernel(name, 1, 1.0, h);
            const double step = 1e-5;
            double oddSum = 0.0;
            for (int k = 1; k < kernel->supportRadius(); k += 2)
            {
                oddSum += (kernel->dWdr(k + step) - kernel->dWdr(k - step)) / step; // ±k
            }
            const double M0 = latticeSums<1>(*kernel, Vec<1>(0.0), sawtooth).M(0, 0);
            const double slope = -2.0 * h * oddSum / M0;
            const double r = schemeResponse<1>(name, h, Vec<1>(beta), sawtooth, Vec<1>(1.0))[0];
            INFO(name << " h/dx = " << h << " slope " << slope << " r/beta " << r / beta);
            CHECK(std::abs(r / beta - slope) < 1e-4 * std::max(1.0, std::abs(slope)));
        }
    }
}

TEST_CASE("vidal with the cubic spline: the sawtooth response is linear in beta between knots",
          "[vidal][modes]")
{
    // (V3.3): r = -2 hβ Δx² S₂ / M(hβ) exactly while |hβ| < d(h) (V3.4), S₂ the odd sum of W''
    // written from the cubic's w'' (not the kernel code); S₂ = 0 for 1.5 ≤ h/Δx ≤ 2.5 (V3.5).
    const std::array<int, 1> sawtooth{1};
    for (const double h : {1.2, 1.3, 1.4, 1.6, 1.8, 2.2, 2.4, 2.6})
    {
        double oddSum = 0.0;
        double knot = 1.0; // j = 0: the odd neighbours themselves
        for (int k = 1; k <= 9; k += 2)
        {
            oddSum += 2.0 * cubicSecondDerivative(k, h);
            for (const int j : {1, 2})
            {
                knot = std::min(knot, std::abs(k - j * h));
            }
        }
        const auto kernel = test::makeKernel("cubicSpline", 1, 1.0, h);
        for (const double fraction : {-0.9, 0.25, 0.5, 0.9})
        {
            const double beta = fraction * knot / h;
            const double M = latticeSums<1>(*kernel, Vec<1>(h * beta), sawtooth).M(0, 0);
            const double r =
                schemeResponse<1>("cubicSpline", h, Vec<1>(beta), sawtooth, Vec<1>(1.0))[0];
            INFO("h/dx = " << h << " beta = " << beta << " S2 = " << oddSum);
            CHECK(std::abs(r - (-2.0 * h * beta * oddSum / M)) < 1e-13);
        }
        const bool dead = h >= 1.5 && h <= 2.5;
        CHECK((std::abs(oddSum) < 1e-15) == dead);
    }
    // Past the nearest knot (d = 0.2 at h = 1.6Δx) the response returns.
    CHECK(std::abs(schemeResponse<1>("cubicSpline", 1.6, Vec<1>(0.3), sawtooth, Vec<1>(1.0))[0]) >
          0.01);
}

TEST_CASE("vidal at h = 2dx: B-spline kernels do not see the sawtooth at any shift",
          "[vidal][modes]")
{
    // (V4.3): the odd sublattice is spaced h, and a B-spline's shifts by its knot spacing sum to
    // a constant. The Wendland kernel is no B-spline: it does see it.
    const std::array<int, 1> sawtooth{1};
    for (const double beta : {0.05, 0.1, 0.2, 0.3, 0.5, 0.7})
    {
        INFO("beta = " << beta);
        for (const std::string kernel : {"cubicSpline", "quinticSpline"})
        {
            CHECK(std::abs(schemeResponse<1>(kernel, 2.0, Vec<1>(beta), sawtooth, Vec<1>(1.0))[0]) <
                  1e-13);
        }
    }
    CHECK(std::abs(schemeResponse<1>("wendlandC2", 2.0, Vec<1>(0.1), sawtooth, Vec<1>(1.0))[0]) >
          0.01);
}

TEST_CASE("vidal's 2D mode responses are the lattice sums of the derivation", "[vidal][modes]")
{
    const std::array<std::array<int, 2>, 3> modes{{{1, 0}, {0, 1}, {1, 1}}};
    const Vec<2> polarisation(0.6, 0.8);
    for (const std::string kernel : {"cubicSpline", "wendlandC2", "quinticSpline"})
    {
        for (const double h : {1.2, 1.3, 1.5, 2.0})
        {
            for (const Vec<2>& beta :
                 {Vec<2>(0.1, 0.0), Vec<2>(0.3, 0.0), Vec<2>(0.2, 0.2), Vec<2>(-0.1, 0.25)})
            {
                for (const auto& n : modes)
                {
                    const Vec<2> r = schemeResponse<2>(kernel, h, beta, n, polarisation);
                    const Vec<2> predicted = predictedResponse<2>(kernel, h, beta, n);
                    INFO(kernel << " h/dx = " << h << " beta = " << beta.transpose() << " n = ("
                                << n[0] << ", " << n[1] << ")");
                    CHECK((r - predicted).norm() <= 1e-12 * std::max(1.0, predicted.norm()));
                }
            }
        }
    }
}

TEST_CASE("vidal in 2D: a shift along x leaves the checkerboard and the y sawtooth near zero",
          "[vidal][modes]")
{
    // §V5: the sawtooth along β is seen through Ŵ(π/Δx); the checkerboard through Ŵ(√2 π/Δx),
    // the sawtooth across β through the aliases |ω| ≥ 2π/Δx only.
    const Vec<2> c(1.0, 0.0);
    double largestHidden = 0.0; // β = 0.1, 0.3 (the issue's)
    double largestAt02 = 0.0;
    for (const double h : {1.2, 1.3, 1.5, 2.0})
    {
        for (const double beta : {0.1, 0.2, 0.3})
        {
            const Vec<2> b(beta, 0.0);
            const double along = schemeResponse<2>("cubicSpline", h, b, {1, 0}, c).norm();
            const double across = schemeResponse<2>("cubicSpline", h, b, {0, 1}, c).norm();
            const double checkerboard = schemeResponse<2>("cubicSpline", h, b, {1, 1}, c).norm();
            std::cout << "vidal 2D cubic h/dx=" << h << " beta=(" << beta << " 0): sawtooth along "
                      << along << ", across " << across << ", checkerboard " << checkerboard
                      << "\n";
            if (h != 1.3)
            {
                double& largest = beta == 0.2 ? largestAt02 : largestHidden;
                largest = std::max({largest, across, checkerboard});
            }
            if (h < 2.0)
            {
                CHECK(along > 2.0 * std::max(across, checkerboard));
            }
        }
    }
    CHECK(largestHidden < 0.0135); // issue 34: ≤ 0.013
    CHECK(largestAt02 < 0.014);    // the checkerboard at h = 1.5Δx: 0.0138
    // Not at h = 1.3Δx: the full lattice's aliases give the y sawtooth 0.022 at β = 0.2 e_x.
    CHECK(schemeResponse<2>("cubicSpline", 1.3, Vec<2>(0.2, 0.0), {0, 1}, c).norm() > 0.02);
}
