#pragma once
// The logarithmic law without principal axes in 3D (docs/theory/plasticity.md §P12), N points
// side by side: the strain ε = ½ ln be of a symmetric be near a dilation, exp(2ε) back, and the
// largest |principal value| of a symmetric matrix. A symmetric 3×3 is held as six lanes (00, 11,
// 22, 01, 02, 12). (In 2D the law has a closed form without axes, cheaper than the series:
// PlaneLanes.hpp.)

#include "materials/plasticity/LaneFunctions.hpp"

#include <algorithm>
#include <cmath>

namespace sph
{

template <int N>
using SymmetricLanes = Lane<N>[6];

namespace tensorLanes
{

// (P12.2)–(P12.3): the isochoric part's logarithm by its series where |b̄ − 1|_F ≤ seriesRange
// (then the terms left out are below 2e-17 of the result), the degrees of the two series.
constexpr double seriesRange = 0.05;
constexpr int logDegree = 12;
constexpr int expDegree = 10;

// out = a b for symmetric a and b that commute (polynomials in one matrix: the product is then
// symmetric, and only its upper triangle is computed).
template <int N>
[[gnu::always_inline]] inline void multiplyCommuting(const SymmetricLanes<N>& a,
                                                     const SymmetricLanes<N>& b,
                                                     SymmetricLanes<N>& out)
{
    for (int i = 0; i < N; ++i)
    {
        out[0][i] = a[0][i] * b[0][i] + a[3][i] * b[3][i] + a[4][i] * b[4][i];
        out[1][i] = a[3][i] * b[3][i] + a[1][i] * b[1][i] + a[5][i] * b[5][i];
        out[2][i] = a[4][i] * b[4][i] + a[5][i] * b[5][i] + a[2][i] * b[2][i];
        out[3][i] = a[0][i] * b[3][i] + a[3][i] * b[1][i] + a[4][i] * b[5][i];
        out[4][i] = a[0][i] * b[4][i] + a[3][i] * b[5][i] + a[4][i] * b[2][i];
        out[5][i] = a[3][i] * b[4][i] + a[1][i] * b[5][i] + a[5][i] * b[2][i];
    }
}

// |a|_F² lane by lane (off-diagonals twice).
template <int N>
inline Lane<N> squaredNorm(const SymmetricLanes<N>& a)
{
    return a[0] * a[0] + a[1] * a[1] + a[2] * a[2] + 2.0 * (a[3] * a[3] + a[4] * a[4] + a[5] * a[5]);
}

// A polynomial in a symmetric 3×3 a, held as α 1 + β a + γ a² (P12.5): by Cayley–Hamilton,
// a³ = I1 a² − I2 a + I3 1 with a's invariants, so a Horner step of a matrix series is a step
// on three numbers per point instead of a product of matrices.
template <int N>
struct PolynomialLanes
{
    Lane<N> alpha, beta, gamma;
    Lane<N> I1, I2, I3; // a's invariants

    [[gnu::always_inline]] explicit PolynomialLanes(const SymmetricLanes<N>& a)
        : alpha(Lane<N>::Zero()), beta(Lane<N>::Zero()), gamma(Lane<N>::Zero())
    {
        I1 = a[0] + a[1] + a[2];
        I2 = a[0] * a[1] + a[1] * a[2] + a[0] * a[2] - a[3] * a[3] - a[4] * a[4] - a[5] * a[5];
        I3 = a[0] * (a[1] * a[2] - a[5] * a[5]) - a[3] * (a[3] * a[2] - a[5] * a[4]) +
             a[4] * (a[3] * a[5] - a[1] * a[4]);
    }
    // p ← a p.
    [[gnu::always_inline]] void multiplyByA()
    {
        const Lane<N> g = gamma;
        gamma = multiplyAdd<N>(g, I1, beta);
        beta = multiplyAdd<N>(-g, I2, alpha);
        alpha = g * I3;
    }
    // The matrix α 1 + β a + γ a² (aSquared = a²).
    void assemble(const SymmetricLanes<N>& a, const SymmetricLanes<N>& aSquared,
                  SymmetricLanes<N>& out) const
    {
        for (int c = 0; c < 6; ++c)
        {
            out[c] = beta * a[c] + gamma * aSquared[c];
            if (c < 3)
            {
                out[c] += alpha;
            }
        }
    }
};

// (P12.1)–(P12.2): ε = ½ ln be of N symmetric positive-definite be, as a strain of six
// components (ReturnLanes.hpp). inRange[i] = 1 where the series
// applies (|b̄ − 1|_F ≤ seriesRange and det be > 0), 0 elsewhere (ε is then not meaningful).
template <int N>
void logarithmicStrain(const SymmetricLanes<N>& be, StrainLanes<N, 6>& strain, Lane<N>& inRange)
{
    Lane<N> det;
    for (int i = 0; i < N; ++i)
    {
        det[i] = be[0][i] * (be[1][i] * be[2][i] - be[5][i] * be[5][i]) -
                 be[3][i] * (be[3][i] * be[2][i] - be[5][i] * be[4][i]) +
                 be[4][i] * (be[3][i] * be[5][i] - be[1][i] * be[4][i]);
    }
    // εv = ½ ln det be and (det be)^(−1/3) = exp(−⅔ εv) by their series (P12.6).
    const Lane<N> volumetric = (det > 0.0).select(0.5 * laneFunctions::logarithm<N>(det), 0.0);
    const Lane<N> scale = laneFunctions::exponential<N>(volumetric * (-2.0 / 3.0));
    SymmetricLanes<N> e;
    for (int c = 0; c < 6; ++c)
    {
        e[c] = be[c] * scale - (c < 3 ? 1.0 : 0.0);
    }
    const Lane<N> size = squaredNorm<N>(e);
    for (int i = 0; i < N; ++i)
    {
        const bool ok = det[i] > 0.0 && size[i] <= seriesRange * seriesRange;
        inRange[i] = ok ? 1.0 : 0.0;
    }
    // Q = Σ_{j<n} (−1)^j e^j/(j+1) by Horner, from the highest power down, and ln b̄ = e Q(e),
    // in the algebra of e (P12.5).
    PolynomialLanes<N> q(e);
    q.alpha = Lane<N>::Constant(((logDegree - 1) % 2 == 0 ? 1.0 : -1.0) / logDegree);
#pragma GCC unroll 16
    for (int j = logDegree - 2; j >= 0; --j)
    {
        q.multiplyByA();
        q.alpha += (j % 2 == 0 ? 1.0 : -1.0) / (j + 1);
    }
    q.multiplyByA();
    SymmetricLanes<N> eSquared, logarithm;
    multiplyCommuting<N>(e, e, eSquared);
    q.assemble(e, eSquared, logarithm);
    // (Thirds as products: a division here was what the loop waited on.)
    constexpr double third = 1.0 / 3.0;
    for (int i = 0; i < N; ++i)
    {
        // tr ln b̄ = 0 up to round-off: the deviator is taken explicitly.
        const double trace = (logarithm[0][i] + logarithm[1][i] + logarithm[2][i]) * third;
        for (int c = 0; c < 6; ++c)
        {
            const double dev = 0.5 * (c < 3 ? logarithm[c][i] - trace : logarithm[c][i]);
            strain.eps[c][i] = c < 3 ? dev + volumetric[i] * third : dev;
        }
    }
}

// be = exp(2ε) of N strains of six components (the update of §P4 step 4 by (P12.1)):
// exp(⅔ εv) exp(2 dev ε), the second by its Horner series to expDegree (valid for the returned
// strains of points in range: |2 dev ε|_F ≤ 0.052).
template <int N>
void exponentialOfTwice(const DeviatorLanes<N, 6>& strain, SymmetricLanes<N>& be)
{
    SymmetricLanes<N> x, xSquared, sum;
    for (int c = 0; c < 6; ++c)
    {
        x[c] = 2.0 * strain.dev[c];
    }
    // exp(x) = Σ x^k/k! by Horner in the algebra of x (P12.5), from the highest power down.
    PolynomialLanes<N> p(x);
    p.alpha = Lane<N>::Constant(laneFunctions::inverseFactorials[expDegree]);
#pragma GCC unroll 16
    for (int k = expDegree - 1; k >= 0; --k)
    {
        p.multiplyByA();
        p.alpha += laneFunctions::inverseFactorials[static_cast<std::size_t>(k)];
    }
    multiplyCommuting<N>(x, x, xSquared);
    p.assemble(x, xSquared, sum);
    const Lane<N> dilation = laneFunctions::exponential<N>(strain.volumetric * (2.0 / 3.0));
    for (int c = 0; c < 6; ++c)
    {
        be[c] = sum[c] * dilation;
    }
}

// maxᵢ |λᵢ(a)| of N symmetric matrices (the stress term of the wave-speed bound (P2.5)). With
// b = a − m 1 (m = tr a/3) and its invariants J2 = ½ tr b², J3 = det b, the eigenvalues of b are
// the roots of λ³ − J2 λ − J3. The root of largest magnitude is simple and has the sign of J3;
// Newton's iteration from the bound 2√(J2/3) (reached by an axisymmetric b) descends to it
// monotonically, the cubic being convex on that side, and six steps reach round-off (from the
// farthest start, a pure shear, the error goes 0.15, 0.03, 1e-3, 1e-6, 1e-12). The other two
// roots, (−λ ± √(4 J2 − 3 λ²))/2, lose digits only where they nearly coincide (√ε_mach of their
// spread: §P12). No arccos.
template <int N>
Lane<N> largestAbsoluteEigenvalue(const SymmetricLanes<N>& a)
{
    Lane<N> result;
    for (int i = 0; i < N; ++i)
    {
        const double m = (a[0][i] + a[1][i] + a[2][i]) / 3.0;
        const double b0 = a[0][i] - m, b1 = a[1][i] - m, b2 = a[2][i] - m;
        const double b3 = a[3][i], b4 = a[4][i], b5 = a[5][i];
        const double J2 = 0.5 * (b0 * b0 + b1 * b1 + b2 * b2) + (b3 * b3 + b4 * b4 + b5 * b5);
        const double J3 =
            b0 * (b1 * b2 - b5 * b5) - b3 * (b3 * b2 - b5 * b4) + b4 * (b3 * b5 - b1 * b4);
        double root = std::copysign(2.0 * std::sqrt(J2 / 3.0), J3);
        for (int step = 0; step < 6; ++step)
        {
            const double slope = 3.0 * root * root - J2;
            const double value = (root * root - J2) * root - J3;
            root -= slope > 0.0 ? value / slope : 0.0;
        }
        const double spread = std::sqrt(std::max(4.0 * J2 - 3.0 * root * root, 0.0));
        const double largest = std::max(std::abs(m + root), std::abs(m + 0.5 * (spread - root)));
        result[i] = std::max(largest, std::abs(m - 0.5 * (root + spread)));
    }
    return result;
}

} // namespace tensorLanes

} // namespace sph
