#pragma once
// The plane-strain logarithmic law in closed form, without principal axes
// (docs/theory/plasticity.md §P13), N points side by side: ε = ½ ln be of an in-plane 2×2 block
// and its zz component from one polynomial, A(s) = atanh(√s)/√s, evaluated in lanes (no call to
// the C library where its series applies), exp(2ε) back for a flowing point, and the largest
// |principal value| of a plane-strain stress. The strain is held as the four components of a
// plane strain's symmetric 3×3 (00, 11, 22, 01; its out-of-plane shears are zero, and nothing
// is computed for them).

#include "materials/plasticity/LaneFunctions.hpp"

#include <algorithm>
#include <cmath>

namespace sph
{

namespace planeLanes
{

using laneFunctions::seriesRange;
using laneFunctions::seriesTerms;

// (P13.1): ε = ½ ln be of N plane-strain be (the in-plane block b, symmetrised, and be_zz).
// The three series (ln det b, ln be_zz and the shape's A(x²)) are independent chains of
// multiply-adds, written side by side so that they overlap; each is laneFunctions::atanhSeries'
// Horner sum.
template <int N>
void logarithmicStrain(const Lane<N> (&be)[2][2], const Lane<N>& beZZ, StrainLanes<N, 4>& strain)
{
    const Lane<N> b01 = 0.5 * (be[0][1] + be[1][0]);
    const Lane<N> m = 0.5 * (be[0][0] + be[1][1]);
    const Lane<N> d = 0.5 * (be[0][0] - be[1][1]);
    const Lane<N> det = be[0][0] * be[1][1] - b01 * b01;
    const Lane<N> x2 = (d * d + b01 * b01) / (m * m); // (r/m)²
    const Lane<N> tDet = (det - 1.0) / (det + 1.0);
    const Lane<N> t2Det = tDet * tDet;
    Lane<N> shape = Lane<N>::Constant(1.0 / (2 * seriesTerms - 1));
    Lane<N> seriesDet = shape;
    Lane<N> lnZZ = Lane<N>::Zero();
    // be_zz = 1 at every lane (no plastic flow yet, the common case): ln be_zz = 2·0·A = 0
    // without its chain (and without its division).
    if (countLanes<N>([&](int i) { return beZZ[i] != 1.0; }) == 0)
    {
        for (int k = seriesTerms - 2; k >= 0; --k)
        {
            const double coefficient = 1.0 / (2 * k + 1);
            shape = shape * x2 + coefficient;
            seriesDet = seriesDet * t2Det + coefficient;
        }
    }
    else
    {
        const Lane<N> tZZ = (beZZ - 1.0) / (beZZ + 1.0);
        const Lane<N> t2ZZ = tZZ * tZZ;
        Lane<N> seriesZZ = shape;
        for (int k = seriesTerms - 2; k >= 0; --k)
        {
            const double coefficient = 1.0 / (2 * k + 1);
            shape = shape * x2 + coefficient;
            seriesDet = seriesDet * t2Det + coefficient;
            seriesZZ = seriesZZ * t2ZZ + coefficient;
        }
        lnZZ = 2.0 * tZZ * seriesZZ;
        laneFunctions::logarithmBeyondSeries<N>(beZZ, t2ZZ, lnZZ);
    }
    Lane<N> lnDet = 2.0 * tDet * seriesDet;
    laneFunctions::logarithmBeyondSeries<N>(det, t2Det, lnDet);
    if (countLanes<N>([&](int i) { return !(x2[i] <= seriesRange); }) > 0)
    {
        for (int i = 0; i < N; ++i)
        {
            if (!(x2[i] <= seriesRange))
            {
                const double x = std::sqrt(x2[i]);
                shape[i] = std::atanh(x) / x;
            }
        }
    }
    const Lane<N> volume = 0.25 * lnDet;
    const Lane<N> scale = shape / (2.0 * m); // ½ atanh(x)/r
    strain.eps[0] = volume + scale * d;
    strain.eps[1] = volume - scale * d;
    strain.eps[2] = 0.5 * lnZZ;
    strain.eps[3] = scale * b01;
}

// (P13.3)–(P13.4): be = exp(2ε) of N returned strains, the in-plane block B and be_zz, in
// lanes. With a the in-plane mean, δ = (d c; c −d) the in-plane deviator and x² = 4(d² + c²):
// B = e^{2a} (cosh x 1 + 2 (sinh x / x) δ), be_zz = e^{2ε_zz}; cosh x and sinh x / x by their
// even series in x² where x² ≤ hyperbolicRange, the exponentials by laneFunctions::exponential
// (P12.6), the C library beyond (lane by lane: which branch a lane takes depends on its own
// strain only).
constexpr double hyperbolicRange = 1.0 / 16.0; // x ≤ 1/4: an in-plane elastic shear of 12 %
constexpr int hyperbolicTerms = 7;             // the terms left out below x¹⁴/14! < 5e-20

template <int N>
void exponentialOfTwice(const DeviatorLanes<N, 4>& strain, Lane<N> (&B)[2][2], Lane<N>& beZZ)
{
    using laneFunctions::inverseFactorials;
    const Lane<N> third = strain.volumetric / 3.0;
    const Lane<N> a = 0.5 * (strain.dev[0] + strain.dev[1]) + third;
    const Lane<N> d = 0.5 * (strain.dev[0] - strain.dev[1]);
    const Lane<N>& c = strain.dev[3];
    const Lane<N> x2 = 4.0 * (d * d + c * c);
    // cosh x = Σ x^2k/(2k)!, sinh x / x = Σ x^2k/(2k + 1)!, by Horner in x².
    Lane<N> coshX = Lane<N>::Constant(inverseFactorials[2 * hyperbolicTerms - 2]);
    Lane<N> sinhXOverX = Lane<N>::Constant(inverseFactorials[2 * hyperbolicTerms - 1]);
#pragma GCC unroll 16
    for (int k = hyperbolicTerms - 2; k >= 0; --k)
    {
        coshX = multiplyAdd<N>(coshX, x2, inverseFactorials[static_cast<std::size_t>(2 * k)]);
        sinhXOverX =
            multiplyAdd<N>(sinhXOverX, x2, inverseFactorials[static_cast<std::size_t>(2 * k + 1)]);
    }
    if (countLanes<N>([&](int i) { return !(x2[i] <= hyperbolicRange); }) > 0)
    {
        for (int i = 0; i < N; ++i)
        {
            if (!(x2[i] <= hyperbolicRange))
            {
                const double x = std::sqrt(x2[i]);
                coshX[i] = std::cosh(x);
                sinhXOverX[i] = std::sinh(x) / x;
            }
        }
    }
    const Lane<N> dilation = laneFunctions::exponential<N>(2.0 * a);
    const Lane<N> diagonal = dilation * coshX;
    const Lane<N> shape = 2.0 * dilation * sinhXOverX;
    B[0][0] = diagonal + shape * d;
    B[1][1] = diagonal - shape * d;
    B[0][1] = shape * c;
    B[1][0] = B[0][1];
    beZZ = laneFunctions::exponential<N>(2.0 * (strain.dev[2] + third));
}

// maxᵢ |τᵢ| of N plane-strain stresses held as four components: the in-plane block's principal
// values, mean ± radius, and τ_zz.
template <int N>
Lane<N> largestAbsolutePrincipal(const Lane<N> (&tau)[4])
{
    Lane<N> result;
    for (int i = 0; i < N; ++i)
    {
        const double mean = 0.5 * (tau[0][i] + tau[1][i]);
        const double half = 0.5 * (tau[0][i] - tau[1][i]);
        const double radius = std::sqrt(half * half + tau[3][i] * tau[3][i]);
        result[i] = std::max(std::abs(mean) + radius, std::abs(tau[2][i]));
    }
    return result;
}

} // namespace planeLanes

} // namespace sph
