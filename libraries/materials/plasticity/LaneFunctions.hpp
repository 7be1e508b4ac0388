#pragma once
// Scalar functions of N lanes without calls to the C library where their series apply
// (docs/theory/plasticity.md (P12.6), (P13.2)): the logarithm near 1 and the exponential near
// 0, the C library's lane by lane elsewhere. Which branch a lane takes depends on its own value,
// so a point gives the same digits in any batch. Used by the laws without principal axes
// (TensorLanes.hpp, PlaneLanes.hpp), whose arguments are elastic volume changes and strains.

#include "materials/plasticity/ReturnLanes.hpp"

#include <array>
#include <cmath>

namespace sph
{

namespace laneFunctions
{

// (P13.2): A(s) = atanh(√s)/√s to `seriesTerms` terms where s ≤ seriesRange; the terms left
// out are then below 7e-19 of A ≥ 1.
constexpr double seriesRange = 1.0 / 49.0;
constexpr int seriesTerms = 10;

// A(s) = Σ_{k<n} s^k/(2k + 1) by Horner, valid (to round-off) for s ≤ seriesRange.
template <int N>
[[gnu::always_inline]] inline Lane<N> atanhSeries(const Lane<N>& s)
{
    Lane<N> sum = Lane<N>::Constant(1.0 / (2 * seriesTerms - 1));
#pragma GCC unroll 16
    for (int k = seriesTerms - 2; k >= 0; --k)
    {
        sum = multiplyAdd<N>(sum, s, 1.0 / (2 * k + 1));
    }
    return sum;
}

// ln y of the lanes where (P13.2)'s series does not apply (t² beyond seriesRange, a NaN
// included), by the C library.
template <int N>
inline void logarithmBeyondSeries(const Lane<N>& y, const Lane<N>& t2, Lane<N>& result)
{
    if (countLanes<N>([&](int i) { return !(t2[i] <= seriesRange); }) == 0)
    {
        return; // the common case: one vector comparison
    }
    for (int i = 0; i < N; ++i)
    {
        if (!(t2[i] <= seriesRange))
        {
            result[i] = std::log(y[i]);
        }
    }
}

// ln y lane by lane (P13.2): 2t A(t²) with t = (y − 1)/(y + 1) where t² ≤ seriesRange
// (y ∈ [3/4, 4/3]), the C library's elsewhere.
template <int N>
inline Lane<N> logarithm(const Lane<N>& y)
{
    const Lane<N> t = (y - 1.0) / (y + 1.0);
    const Lane<N> t2 = t * t;
    Lane<N> result = 2.0 * t * atanhSeries<N>(t2);
    logarithmBeyondSeries<N>(y, t2, result);
    return result;
}

// 1/k! for k ≤ 16, each rounded once (k! itself is exact in a double up to 18!).
constexpr std::array<double, 17> inverseFactorials = [] {
    std::array<double, 17> c{};
    double factorial = 1.0;
    for (std::size_t k = 0; k < c.size(); ++k)
    {
        factorial *= k > 0 ? static_cast<double>(k) : 1.0;
        c[k] = 1.0 / factorial;
    }
    return c;
}();

// exp y = Σ_{k≤n} y^k/k! by Horner with fused multiply-adds, n = expDegree, where
// |y| ≤ expRange (P12.6: the terms left out are below 4e-18 of the result), the C library's
// elsewhere (a NaN included).
constexpr double expRange = 0.125;
constexpr int expDegree = 10;

template <int N>
[[gnu::always_inline]] inline Lane<N> exponential(const Lane<N>& y)
{
    Lane<N> sum = Lane<N>::Constant(inverseFactorials[expDegree]);
#pragma GCC unroll 16
    for (int k = expDegree - 1; k >= 0; --k)
    {
        sum = multiplyAdd<N>(sum, y, inverseFactorials[static_cast<std::size_t>(k)]);
    }
    if (countLanes<N>([&](int i) { return !(std::abs(y[i]) <= expRange); }) > 0)
    {
        for (int i = 0; i < N; ++i)
        {
            if (!(std::abs(y[i]) <= expRange))
            {
                sum[i] = std::exp(y[i]);
            }
        }
    }
    return sum;
}

} // namespace laneFunctions

} // namespace sph
