#pragma once
// The algebra the return map in lanes is written in (ReturnMapLanes.hpp): D×D products of
// lanes, the gathered inputs of N points (F and their packed committed states, the trial be,
// F⁻¹) and the state a flowing point commits.

#include "materials/plasticity/PlasticHistory.hpp"
#include "materials/plasticity/ReturnLanes.hpp"

#include <Eigen/Core>

#include <type_traits>

namespace sph
{

namespace lanes
{

// out = Σₘ a(k, m) b(m, l), D×D, with a and b read through callables (a lane of an array of
// lanes, or a plain matrix).
template <int D, class A, class B>
inline void multiply(const A& a, const B& b, double (&out)[D][D])
{
    for (int k = 0; k < D; ++k)
    {
        for (int l = 0; l < D; ++l)
        {
            out[k][l] = 0.0;
            for (int m = 0; m < D; ++m)
            {
                out[k][l] += a(k, m) * b(m, l);
            }
        }
    }
}

// Σₘ a(m) b(m) over m < D at lane i: in 3D by fused multiply-adds (docs/theory/plasticity.md
// §P12, "Fused multiply-adds"), in 2D a product and a sum each, as it always was (2D keeps its
// digits: its law did not get faster with fused steps).
template <int D, class A, class B>
[[gnu::always_inline]] inline double dotAt(const A& a, const B& b, int i)
{
    if constexpr (D == 3)
    {
        return multiplyAdd(a(2)[i], b(2)[i], multiplyAdd(a(1)[i], b(1)[i], a(0)[i] * b(0)[i]));
    }
    else
    {
        double sum = 0.0;
        for (int m = 0; m < D; ++m)
        {
            sum += a(m)[i] * b(m)[i];
        }
        return sum;
    }
}

// out = Σₘ a(k, m) b(m, l) lane by lane, D×D, a and b returning lanes (or maps of them).
template <int N, int D, class A, class B>
inline void multiplyLanes(const A& a, const B& b, Lane<N> (&out)[D][D])
{
    // (Unrolled: the compiler left the 3D loops rolled, computing each operand's place at run
    // time.)
#pragma GCC unroll 3
    for (int k = 0; k < D; ++k)
    {
#pragma GCC unroll 3
        for (int l = 0; l < D; ++l)
        {
            for (int i = 0; i < N; ++i)
            {
                out[k][l][i] = dotAt<D>([&](int m) -> decltype(auto) { return a(k, m); },
                                        [&](int m) -> decltype(auto) { return b(m, l); }, i);
            }
        }
    }
}

// Σₘ values[m] nₘ⊗nₘ of lane i, the directions nₘ the columns of `vectors`.
template <int N, int D>
inline void assemble(const Lane<N> (&vectors)[D][D], int i, const Eigen::Vector3d& values,
                     double (&out)[D][D])
{
    for (int k = 0; k < D; ++k)
    {
        for (int l = 0; l < D; ++l)
        {
            out[k][l] = 0.0;
            for (int m = 0; m < D; ++m)
            {
                out[k][l] += values[m] * vectors[k][m][i] * vectors[l][m][i];
            }
        }
    }
}

} // namespace lanes

// The inputs of N points: F and the packed committed states (Cp⁻¹ with all D² components, as
// a packed state holds them, zz in 2D, the flow pressure and α). Unused lanes hold the virgin
// state at F = I, where every branch is finite. The states packed one after another (stride
// apart), or in rows (componentStride apart, HistoryOf::samplesInRows: N entries of each row
// readable, those past `count` the initial state's), read where they are: only α, the flow
// pressure and zz, which the returns take as lanes, are copied (copying every row cost 2-3 % of
// a return in lanes, docs/performance.md).
template <int D, int N, class State>
struct GatheredLanes
{
    static constexpr int zz = D * D;                       // 2D: Cp⁻¹_zz's place in a packed state
    static constexpr int alphaAt = State::packedSize - 1; // α's
    static constexpr int pressureAt = State::flowPressureAt;
    Lane<N> f[D][D];

    GatheredLanes(const Mat<D>* F, const double* states, std::size_t stride, std::size_t count,
                  std::size_t componentStride = 1)
    {
        gatherF(F, count);
        if (componentStride != 1)
        {
            for (int c = 0; c < static_cast<int>(State::packedSize); ++c)
            {
                row_[c] = states + c * componentStride;
            }
        }
        else
        {
            for (int c = 0; c < static_cast<int>(State::packedSize); ++c)
            {
                const bool unit =
                    c != alphaAt && c != pressureAt && (c == zz || (c < zz && c / D == c % D));
                packed_[c] =
                    Lane<N>::Constant(c == pressureAt ? noFlowPressure : unit ? 1.0 : 0.0);
            }
            for (std::size_t i = 0; i < count; ++i)
            {
                for (int c = 0; c < static_cast<int>(State::packedSize); ++c)
                {
                    packed_[c][i] = states[i * stride + c];
                }
            }
            for (int c = 0; c < static_cast<int>(State::packedSize); ++c)
            {
                row_[c] = packed_[c].data();
            }
        }
        alpha_ = committed(alphaAt);
        flowPressure_ = committed(pressureAt);
        if constexpr (D == 2)
        {
            zz_ = committed(zz);
        }
    }
    // (It points into its own storage.)
    GatheredLanes(const GatheredLanes&) = delete;
    GatheredLanes& operator=(const GatheredLanes&) = delete;

    // Component c of the N committed states.
    Eigen::Map<const Lane<N>> committed(int c) const
    {
        return Eigen::Map<const Lane<N>>(row_[c]);
    }
    // F of the first `count` lanes, I in the others.
    void gatherF(const Mat<D>* F, std::size_t count)
    {
        const auto copy = [&](auto lanes)
        {
            for (std::size_t i = 0; i < static_cast<std::size_t>(lanes); ++i)
            {
                for (int k = 0; k < D; ++k)
                {
                    for (int l = 0; l < D; ++l)
                    {
                        f[k][l][i] = F[i](k, l);
                    }
                }
            }
        };
        if (count == static_cast<std::size_t>(N))
        {
            // A whole block (most of them): compile-time bounds, which the compiler
            // vectorises as a transposition.
            copy(std::integral_constant<std::size_t, N>{});
            return;
        }
        for (int k = 0; k < D; ++k)
        {
            for (int l = 0; l < D; ++l)
            {
                f[k][l] = Lane<N>::Constant(k == l ? 1.0 : 0.0);
            }
        }
        copy(count);
    }
    const Lane<N>& alpha() const { return alpha_; }
    // The states to commit before any flow is written in: the committed ones, with the flow
    // pressure of the return (noFlowPressure where the point does not flow). Where no lane
    // flows, a row at a time (copies that vectorise); where some do, and writeFlowingStates
    // writes their lanes next, a lane at a time (the lanes' loop that follows was 8-10 % slower
    // after the row copies; docs/performance.md).
    template <class Result> void keepCommitted(Result& out, bool someFlow) const
    {
        if (!someFlow)
        {
            for (int c = 0; c < static_cast<int>(State::packedSize); ++c)
            {
                if (c != pressureAt)
                {
                    out.next[c] = committed(c);
                }
            }
            out.next[pressureAt] = out.flow.pressure;
            return;
        }
        for (int i = 0; i < N; ++i)
        {
            for (int c = 0; c < static_cast<int>(State::packedSize); ++c)
            {
                out.next[c][i] = row_[c][i];
            }
            out.next[pressureAt][i] = out.flow.pressure[i];
        }
    }
    const Lane<N>& flowPressure() const { return flowPressure_; }
    // be_zz in 2D (Cp⁻¹_zz: F has no zz part).
    const Lane<N>& trialZZ() const { return D == 2 ? zz_ : alpha_; }

    // be = (F Cp⁻¹) Fᵀ, the trial's elastic left Cauchy–Green tensor (in-plane in 2D). (Each
    // loop over the lanes vectorises.)
    void trialBe(Lane<N> (&be)[D][D]) const
    {
        Lane<N> t[D][D];
        lanes::multiplyLanes<N, D>([&](int k, int m) -> const Lane<N>& { return f[k][m]; },
                                   [&](int m, int l) { return committed(m * D + l); }, t);
        if constexpr (D == 3)
        {
            // be is symmetric: its upper triangle, mirrored.
#pragma GCC unroll 3
            for (int k = 0; k < D; ++k)
            {
#pragma GCC unroll 3
                for (int l = k; l < D; ++l)
                {
                    const auto row = [&](int m) -> const Lane<N>& { return t[k][m]; };
                    const auto column = [&](int m) -> const Lane<N>& { return f[l][m]; };
                    for (int i = 0; i < N; ++i)
                    {
                        be[k][l][i] = lanes::dotAt<D>(row, column, i);
                    }
                }
            }
            for (int k = 0; k < D; ++k)
            {
                for (int l = 0; l < k; ++l)
                {
                    be[k][l] = be[l][k];
                }
            }
        }
        else
        {
            lanes::multiplyLanes<N, D>([&](int k, int m) -> const Lane<N>& { return t[k][m]; },
                                       [&](int m, int l) -> const Lane<N>& { return f[l][m]; }, be);
        }
    }
    // F⁻¹ by cofactors (the transposed cofactor matrix over det F).
    void inverse(Lane<N> (&finv)[D][D]) const
    {
        if constexpr (D == 2)
        {
            for (int i = 0; i < N; ++i)
            {
                const double invDet = 1.0 / (f[0][0][i] * f[1][1][i] - f[0][1][i] * f[1][0][i]);
                finv[0][0][i] = f[1][1][i] * invDet;
                finv[0][1][i] = -f[0][1][i] * invDet;
                finv[1][0][i] = -f[1][0][i] * invDet;
                finv[1][1][i] = f[0][0][i] * invDet;
            }
        }
        else
        {
            Lane<N> cof[3][3];
            // (Unrolled: with the indices known, no modulo is computed at run time.)
#pragma GCC unroll 3
            for (int k = 0; k < 3; ++k)
            {
#pragma GCC unroll 3
                for (int l = 0; l < 3; ++l)
                {
                    const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
                    const int l1 = (l + 1) % 3, l2 = (l + 2) % 3;
                    for (int i = 0; i < N; ++i)
                    {
                        cof[k][l][i] = f[k1][l1][i] * f[k2][l2][i] - f[k1][l2][i] * f[k2][l1][i];
                    }
                }
            }
            for (int i = 0; i < N; ++i)
            {
                const double invDet = 1.0 / (f[0][0][i] * cof[0][0][i] + f[0][1][i] * cof[0][1][i] +
                                             f[0][2][i] * cof[0][2][i]);
                for (int k = 0; k < 3; ++k)
                {
                    for (int l = 0; l < 3; ++l)
                    {
                        finv[k][l][i] = cof[l][k][i] * invDet;
                    }
                }
            }
        }
    }

private:
    const double* row_[State::packedSize]; // component c's N lanes
    Lane<N> packed_[State::packedSize];    // the rows of packed states
    Lane<N> alpha_, flowPressure_, zz_;
};

namespace lanes
{

// Cp⁻¹ = (F⁻¹ B) F⁻ᵀ at lane i, symmetrised: ½ (C + Cᵀ) off the diagonal.
template <int D, int N>
[[gnu::always_inline]] inline void pullBack(const Lane<N> (&finv)[D][D], const double (&B)[D][D],
                                            int i, double (&out)[D][D])
{
    double T[D][D], C[D][D];
    multiply<D>([&](int k, int m) { return finv[k][m][i]; }, [&](int m, int l) { return B[m][l]; },
                T);
    multiply<D>([&](int k, int m) { return T[k][m]; }, [&](int m, int l) { return finv[l][m][i]; },
                C);
    for (int k = 0; k < D; ++k)
    {
        for (int l = 0; l < D; ++l)
        {
            out[k][l] = k == l ? C[k][k] : 0.5 * (C[k][l] + C[l][k]);
        }
    }
}

// The state to commit at lane i of a point that flows: Cp⁻¹ = (F⁻¹ B) F⁻ᵀ, ½ (C + Cᵀ), with B
// the returned be (in-plane), zz = the returned be_zz (2D), α and the flow pressure of the return.
template <int D, int N, class State>
inline void writeFlowingState(const Lane<N> (&finv)[D][D], const double (&B)[D][D], double beZZ,
                              const FlowLanes<N>& flow, int i, Lane<N>* next)
{
    double C[D][D];
    pullBack<D, N>(finv, B, i, C);
    for (int k = 0; k < D; ++k)
    {
        for (int l = 0; l < D; ++l)
        {
            next[k * D + l][i] = C[k][l];
        }
    }
    if constexpr (D == 2)
    {
        next[D * D][i] = beZZ;
    }
    next[State::packedSize - 1][i] = flow.alpha[i];
}

// writeFlowingState() of every lane that flows (deltaGamma > 0), the returned be of lane i
// B(k, l)[i] (and beZZ[i] in 2D), the others left as they are: one loop over the lanes, which
// vectorises (the same operations per lane as writeFlowingState()'s, so the same digits).
template <int D, int N, class State, class Returned>
inline void writeFlowingStates(const Lane<N> (&finv)[D][D], const Returned& B, const Lane<N>& beZZ,
                               const FlowLanes<N>& flow, Lane<N>* next)
{
    for (int i = 0; i < N; ++i)
    {
        double b[D][D], C[D][D];
        for (int k = 0; k < D; ++k)
        {
            for (int l = 0; l < D; ++l)
            {
                b[k][l] = B(k, l)[i];
            }
        }
        pullBack<D, N>(finv, b, i, C);
        const bool flows = flow.deltaGamma[i] > 0.0;
        for (int k = 0; k < D; ++k)
        {
            for (int l = 0; l < D; ++l)
            {
                next[k * D + l][i] = flows ? C[k][l] : next[k * D + l][i];
            }
        }
        if constexpr (D == 2)
        {
            next[D * D][i] = flows ? beZZ[i] : next[D * D][i];
        }
        next[State::packedSize - 1][i] = flows ? flow.alpha[i] : next[State::packedSize - 1][i];
    }
}

} // namespace lanes

} // namespace sph
