#pragma once
// ReturnMapPlasticity's return map at eight points side by side (ReturnLanes.hpp); the paths
// that use it are in ReturnMapPaths.hpp. Included at the end of ReturnMapPlasticity.hpp, whose
// members it defines.
//
// Per lane, as docs/theory/plasticity.md §P1–§P4 write it:
//   be = F Cp⁻¹ Fᵀ (in-plane; in 2D be_zz = Cp⁻¹_zz) = Σ λᵢ² nᵢ⊗nᵢ;  εᵢ = ½ ln λᵢ²;
//   the model's return;  τ(ε);  P = (Σ τᵢ nᵢ⊗nᵢ) F⁻ᵀ;  W = Ψ(ε) (+ the model's extra energy
//   once the point has flowed);  flowing: Cp⁻¹ = F⁻¹ (Σ exp(2εᵢ) nᵢ⊗nᵢ) F⁻ᵀ, symmetrised (and
//   in 2D be_zz = exp(2ε₂)).
// The principal form: in 2D the closed form of principalStrain<2>; in 3D Jacobi rotations
// (JacobiLanes.hpp). The logarithms are the C library's, one lane at a time (Eigen's
// vectorised logarithm differs from it in the last bits, and GCC 12 warns inside its AVX-512
// code). Every path runs the same instructions on a point's lane, so a point gives the same
// digits on every path (test: numericsTests "[lanes]").

#include "materials/plasticity/JacobiLanes.hpp"

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

// out = Σₘ a(k, m) b(m, l) lane by lane, D×D, a and b returning lanes.
template <int N, int D, class A, class B>
inline void multiplyLanes(const A& a, const B& b, Lane<N> (&out)[D][D])
{
    for (int k = 0; k < D; ++k)
    {
        for (int l = 0; l < D; ++l)
        {
            for (int i = 0; i < N; ++i)
            {
                double sum = 0.0;
                for (int m = 0; m < D; ++m)
                {
                    sum += a(k, m)[i] * b(m, l)[i];
                }
                out[k][l][i] = sum;
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

template <int D, class Model>
template <int N>
void ReturnMapPlasticity<D, Model>::returnInLanes(const Mat<D>* F, const double* states,
                                                  std::size_t stride, std::size_t count, bool flow,
                                                  bool wantNext, LanesResult<N>& out) const
{
    static_assert(D == 2 || D == 3, "the bar (1D) has its own return");
    constexpr int zz = D * D;                       // 2D: Cp⁻¹_zz's place in a packed state
    constexpr int alphaAt = State::packedSize - 1; // α's
    constexpr int pressureAt = State::flowPressureAt;
    // Gather: F, Cp⁻¹ (all D² components, as a packed state holds them), zz and α. Unused
    // lanes hold the virgin state at F = I, where every branch is finite.
    Lane<N> f[D][D], committed[State::packedSize];
    for (int k = 0; k < D; ++k)
    {
        for (int l = 0; l < D; ++l)
        {
            f[k][l] = Lane<N>::Constant(k == l ? 1.0 : 0.0);
        }
    }
    for (int c = 0; c < static_cast<int>(State::packedSize); ++c)
    {
        const bool unit = c != alphaAt && c != pressureAt && (c == zz || (c < zz && c / D == c % D));
        committed[c] = Lane<N>::Constant(c == pressureAt ? noFlowPressure : unit ? 1.0 : 0.0);
    }
    for (std::size_t i = 0; i < count; ++i)
    {
        for (int k = 0; k < D; ++k)
        {
            for (int l = 0; l < D; ++l)
            {
                f[k][l][i] = F[i](k, l);
            }
        }
        for (int c = 0; c < static_cast<int>(State::packedSize); ++c)
        {
            committed[c][i] = states[i * stride + c];
        }
    }
    const Lane<N>& alpha = committed[alphaAt];

    // be = (F Cp⁻¹) Fᵀ. (Each loop over the lanes vectorises.)
    Lane<N> t[D][D], be[D][D];
    lanes::multiplyLanes<N, D>([&](int k, int m) -> const Lane<N>& { return f[k][m]; },
                               [&](int m, int l) -> const Lane<N>& { return committed[m * D + l]; },
                               t);
    lanes::multiplyLanes<N, D>([&](int k, int m) -> const Lane<N>& { return t[k][m]; },
                               [&](int m, int l) -> const Lane<N>& { return f[l][m]; }, be);
    PrincipalLanes<N, D> principal;
    principalOf<N>(be, committed[D == 2 ? zz : alphaAt], principal);

    out.flow.pressure = Lane<N>::Constant(noFlowPressure);
    if (flow)
    {
        model().template returnLanes<N>(principal.strain, alpha, committed[pressureAt], out.flow);
    }
    else
    {
        out.flow.deltaGamma = Lane<N>::Zero();
        out.flow.alpha = alpha;
        out.flow.dissipation = Lane<N>::Zero();
    }

    // F⁻¹ by cofactors (the transposed cofactor matrix over det F).
    Lane<N> finv[D][D];
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
        for (int k = 0; k < 3; ++k)
        {
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

    // τ, P = S F⁻ᵀ with S = Σ τₖ nₖ⊗nₖ, W and the wave modulus M + max |τ| (P2.5).
    const auto& v = principal.vectors;
    const DeviatorLanes<N> returned(principal.strain);
    Lane<N> tau[3], S[D][D];
    kirchhoffLanes<N>(returned, tau);
    for (int k = 0; k < D; ++k)
    {
        for (int l = 0; l < D; ++l)
        {
            for (int i = 0; i < N; ++i)
            {
                double sum = 0.0;
                for (int m = 0; m < D; ++m)
                {
                    sum += tau[m][i] * v[k][m][i] * v[l][m][i];
                }
                S[k][l][i] = sum;
            }
        }
    }
    lanes::multiplyLanes<N, D>([&](int k, int m) -> const Lane<N>& { return S[k][m]; },
                               [&](int m, int l) -> const Lane<N>& { return finv[l][m]; }, out.P);
    const Lane<N> modulus = waveModulusLanes<N>(returned);
    for (int i = 0; i < N; ++i)
    {
        out.waveModulus[i] =
            modulus[i] +
            std::max(std::max(std::abs(tau[0][i]), std::abs(tau[1][i])), std::abs(tau[2][i]));
    }
    out.energy = elasticEnergyLanes<N>(returned);
    for (int i = 0; i < N; ++i)
    {
        if (alpha[i] > 0.0 || out.flow.deltaGamma[i] > 0.0)
        {
            // Without plastic flow (now or before) the energy stays Hencky's.
            out.energy[i] += model().extraEnergy(
                Flow{out.flow.deltaGamma[i], out.flow.alpha[i], out.flow.dissipation[i]});
        }
    }
    if (!wantNext)
    {
        return;
    }

    // The states to commit: where the point flows the returned be pulled back (§P4 step 4),
    // elsewhere the committed state; the flow pressure the return's (noFlowPressure where the
    // point does not flow).
    for (int i = 0; i < N; ++i)
    {
        for (int c = 0; c < static_cast<int>(State::packedSize); ++c)
        {
            out.next[c][i] = committed[c][i];
        }
        out.next[pressureAt][i] = out.flow.pressure[i];
        if (!(out.flow.deltaGamma[i] > 0.0))
        {
            continue;
        }
        const Eigen::Vector3d stretch = (2.0 * principal.strain.point(i)).array().exp();
        // Cp⁻¹ = (F⁻¹ B) F⁻ᵀ with B = Σ exp(2εₖ) nₖ⊗nₖ, then ½ (C + Cᵀ).
        double B[D][D], T[D][D], C[D][D];
        lanes::assemble<N, D>(v, i, stretch, B);
        lanes::multiply<D>([&](int k, int m) { return finv[k][m][i]; },
                           [&](int m, int l) { return B[m][l]; }, T);
        lanes::multiply<D>([&](int k, int m) { return T[k][m]; },
                           [&](int m, int l) { return finv[l][m][i]; }, C);
        for (int k = 0; k < D; ++k)
        {
            for (int l = 0; l < D; ++l)
            {
                out.next[k * D + l][i] = k == l ? C[k][k] : 0.5 * (C[k][l] + C[l][k]);
            }
        }
        if constexpr (D == 2)
        {
            out.next[zz][i] = stretch[2];
        }
        out.next[alphaAt][i] = out.flow.alpha[i];
    }
}

template <int D, class Model>
template <int N>
void ReturnMapPlasticity<D, Model>::principalOf(const Lane<N> (&be)[D][D], const Lane<N>& beZZ,
                                                PrincipalLanes<N, D>& out)
{
    if constexpr (D == 2)
    {
        // principalStrain<2>'s closed form: eigenvalues m ± r; the eigenvector of m + r from
        // the row of (be − λ I) with the larger norm.
        // (Local arrays, not `out`'s: the loop vectorises only where it cannot alias `be`.)
        const Lane<N> b00 = be[0][0], b01 = be[0][1], b10 = be[1][0], b11 = be[1][1];
        Lane<N> mean, radius, cosine, sine;
        for (int i = 0; i < N; ++i)
        {
            const double m = 0.5 * (b00[i] + b11[i]);
            const double d = 0.5 * (b00[i] - b11[i]);
            const double b = 0.5 * (b01[i] + b10[i]);
            const double r = std::sqrt(d * d + b * b);
            const double vx = d >= 0.0 ? d + r : b;
            const double vy = d >= 0.0 ? b : r - d;
            const double length = std::sqrt(vx * vx + vy * vy);
            mean[i] = m;
            radius[i] = r;
            cosine[i] = r > 0.0 ? vx / length : 1.0;
            sine[i] = r > 0.0 ? vy / length : 0.0;
        }
        out.vectors[0][0] = cosine;
        out.vectors[1][0] = sine;
        out.vectors[0][1] = -sine;
        out.vectors[1][1] = cosine;
        for (int i = 0; i < N; ++i)
        {
            out.strain.eps[0][i] = 0.5 * std::log(mean[i] + radius[i]);
            out.strain.eps[1][i] = 0.5 * std::log(mean[i] - radius[i]);
            out.strain.eps[2][i] = 0.5 * std::log(beZZ[i]);
        }
    }
    else
    {
        // The symmetric part, as principalStrain<3> takes it.
        Lane<N> a[6];
        for (int k = 0; k < 3; ++k)
        {
            a[k] = be[k][k];
        }
        a[3] = 0.5 * (be[0][1] + be[1][0]);
        a[4] = 0.5 * (be[0][2] + be[2][0]);
        a[5] = 0.5 * (be[1][2] + be[2][1]);
        lanes::principalForm<N>(a, out.vectors);
        for (int k = 0; k < 3; ++k)
        {
            for (int i = 0; i < N; ++i)
            {
                out.strain.eps[k][i] = 0.5 * std::log(a[k][i]);
            }
        }
    }
}

} // namespace sph
