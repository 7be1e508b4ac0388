#pragma once
// N points of the logarithmic law side by side (issue 30: plastic materials at the cost of
// elastic ones; docs/performance.md, "The return in lanes"). A gradF particle evaluates its
// 20-120 stress samples one after another; point by point, the return is a chain of square
// roots and divisions that waits on each result, and its branch "inside the cone or not",
// which a flowing deposit makes unpredictable, throws the work in flight away. In lanes every
// quantity is an array over N points (structure of arrays), every branch is computed both ways
// and one kept per lane, and the loops over lanes vectorise: N square roots in one
// instruction, no branch to mispredict.
//
// A model's return in lanes (ReturnMapPlasticity: `returnLanes`) is its only return: the
// point-by-point return is the same code with N = 1, so the two cannot drift apart. Lanes
// that do not flow come back with Δγ = 0, their strains and α unchanged, whatever the
// discarded branch computed for them (an infinity, a NaN: never kept).

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace sph
{

template <int N>
using Lane = Eigen::Array<double, N, 1>;

// The logarithmic strains of N points, C components each: C = 3 their principal values, C = 6
// the symmetric tensor (00, 11, 22, 01, 02, 12; TensorLanes.hpp), C = 4 a plane strain's
// (00, 11, 22, 01: it has no out-of-plane shears; PlaneLanes.hpp), whose off-diagonal
// components count twice in a norm. The models' returns and elastic laws are written for any C:
// they act on the volumetric part and scale the deviatoric one, which needs no principal axes.
// eps[k][i] is point i's k-th component.
template <int N, int C = 3>
struct StrainLanes
{
    static_assert(C == 3 || C == 4 || C == 6,
                  "principal values (3), a plane strain (4) or a symmetric tensor (6)");
    Lane<N> eps[C];

    Eigen::Vector3d point(int i) const
        requires(C == 3)
    {
        return {eps[0][i], eps[1][i], eps[2][i]};
    }
    void setPoint(int i, const Eigen::Vector3d& e)
        requires(C == 3)
    {
        for (int k = 0; k < 3; ++k)
        {
            eps[k][i] = e[k];
        }
    }
};

// How many of N lanes satisfy pred(i). (A sum, not Eigen's any() or all(): those compile to a
// compare and a branch per lane; this loop is one vector compare per register.)
template <int N, class Predicate>
[[gnu::always_inline]] inline int countLanes(Predicate pred)
{
    int count = 0;
    for (int i = 0; i < N; ++i)
    {
        count += pred(i) ? 1 : 0;
    }
    return count;
}

// a b + c lane by lane, rounded once where the CPU fuses multiply-adds (one instruction, and
// half the latency of a product and a sum, which is what a Horner chain waits on). Written
// with Eigen's packets because the compiler does not vectorise std::fma over lanes, and with
// the same rounding for a lane outside a packet, so that N lanes and one give the same digits.
// (The library is otherwise built without fused multiply-adds, CMakeLists.txt: only the series
// that call this fuse.)
[[gnu::always_inline]] inline double multiplyAdd(double a, double b, double c)
{
#ifdef EIGEN_VECTORIZE_FMA
    return std::fma(a, b, c);
#else
    return a * b + c;
#endif
}
template <int N>
[[gnu::always_inline]] inline Lane<N> multiplyAdd(const Lane<N>& a, const Lane<N>& b,
                                                  const Lane<N>& c)
{
    namespace packets = Eigen::internal;
    using Packet = typename packets::packet_traits<double>::type;
    constexpr int size = packets::packet_traits<double>::size;
    Lane<N> r;
    if constexpr (N % size == 0)
    {
        for (int i = 0; i < N; i += size)
        {
            packets::pstoreu(r.data() + i, packets::pmadd(packets::ploadu<Packet>(a.data() + i),
                                                          packets::ploadu<Packet>(b.data() + i),
                                                          packets::ploadu<Packet>(c.data() + i)));
        }
    }
    else
    {
        for (int i = 0; i < N; ++i)
        {
            r[i] = multiplyAdd(a[i], b[i], c[i]);
        }
    }
    return r;
}
template <int N>
[[gnu::always_inline]] inline Lane<N> multiplyAdd(const Lane<N>& a, const Lane<N>& b, double c)
{
    return multiplyAdd<N>(a, b, Lane<N>::Constant(c));
}

// to[0 .. count) = from[0 .. count) for count ≤ N, by copies of a length known at compile
// time: a whole block's, or over all N lanes writing those below count. (A copy of a length
// known only at run time was a call of the C library's memmove, 1.7 % of a yielding 2D step.)
template <int N, class T>
[[gnu::always_inline]] inline void copyFirst(const T* from, T* to, std::size_t count)
{
    if (count == static_cast<std::size_t>(N))
    {
        std::copy(from, from + N, to);
        return;
    }
    for (std::size_t i = 0; i < static_cast<std::size_t>(N); ++i)
    {
        if (i < count)
        {
            to[i] = from[i];
        }
    }
}

// Whether component k of a strain's C is on the diagonal (a principal value is).
constexpr bool onDiagonal(int k) { return k < 3; }

// N symmetric positive-definite D×D matrices (be) in principal form: the principal log
// strains (in 2D the third is zz's) and the directions, vectors[i][k] the i-th component of
// direction k.
template <int N, int D>
struct PrincipalLanes
{
    StrainLanes<N> strain;
    Lane<N> vectors[D][D];
};

// What a return did at N points (PlasticFlow's fields, lane by lane). pressure starts as
// noFlowPressure; a model that keeps a flow pressure sets it where the point flows.
template <int N>
struct FlowLanes
{
    Lane<N> deltaGamma;
    Lane<N> alpha;
    Lane<N> dissipation;
    Lane<N> pressure;
};

// The volumetric and deviatoric parts of N points' strains, computed as the point-by-point
// law always has: εv = (ε0 + ε1) + ε2, e = ε − εv/3 (on the diagonal), |e|.
template <int N, int C = 3>
struct DeviatorLanes
{
    Lane<N> volumetric;
    Lane<N> dev[C];
    Lane<N> norm;

    DeviatorLanes() = default; // (uninitialised: split() fills it)
    [[gnu::always_inline]] explicit DeviatorLanes(const StrainLanes<N, C>& s) { split(s); }
    [[gnu::always_inline]] void split(const StrainLanes<N, C>& s)
    {
        for (int i = 0; i < N; ++i)
        {
            const double ev = s.eps[0][i] + s.eps[1][i] + s.eps[2][i];
            volumetric[i] = ev;
            for (int k = 0; k < C; ++k)
            {
                dev[k][i] = onDiagonal(k) ? s.eps[k][i] - ev / 3.0 : s.eps[k][i];
            }
        }
        for (int i = 0; i < N; ++i)
        {
            norm[i] = std::sqrt(squaredNorm(i));
        }
    }
    // |e|² of point i (a tensor's off-diagonal components twice).
    double squaredNorm(int i) const
    {
        const double diagonal = dev[0][i] * dev[0][i] + dev[1][i] * dev[1][i] + dev[2][i] * dev[2][i];
        if constexpr (C == 3)
        {
            return diagonal;
        }
        else if constexpr (C == 4)
        {
            return diagonal + 2.0 * (dev[3][i] * dev[3][i]);
        }
        else
        {
            return diagonal + 2.0 * (dev[3][i] * dev[3][i] + dev[4][i] * dev[4][i] +
                                     dev[5][i] * dev[5][i]);
        }
    }
};

} // namespace sph
