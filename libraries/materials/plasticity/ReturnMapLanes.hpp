#pragma once
// ReturnMapPlasticity's return map at `lanes` (16) points side by side (ReturnLanes.hpp); the
// paths that use it are in ReturnMapPaths.hpp. Included at the end of ReturnMapPlasticity.hpp,
// whose members it defines.
//
// Per lane, as docs/theory/plasticity.md §P1–§P4 write it:
//   be = F Cp⁻¹ Fᵀ (in-plane; in 2D be_zz = Cp⁻¹_zz) = Σ λᵢ² nᵢ⊗nᵢ;  εᵢ = ½ ln λᵢ²;
//   the model's return;  τ(ε);  P = (Σ τᵢ nᵢ⊗nᵢ) F⁻ᵀ;  W = Ψ(ε) (+ the model's extra energy
//   once the point has flowed);  flowing: Cp⁻¹ = F⁻¹ (Σ exp(2εᵢ) nᵢ⊗nᵢ) F⁻ᵀ, symmetrised (and
//   in 2D be_zz = exp(2ε₂)).
// Two forms of the same law (docs/theory/plasticity.md §P12–§P13): without principal axes (the
// return on the tensor's volumetric part and deviator) — in 3D where the isochoric part of be is
// within the series' range (TensorLanes.hpp: ε = ½ ln be and exp(2ε) by their series), in
// principal axes elsewhere, point by point; in 2D everywhere, in closed form (PlaneLanes.hpp:
// one polynomial for the logarithms and the shape) — and, with `logarithm principalAxes`, in
// principal axes everywhere: in 2D the closed form of principalStrain<2>, in 3D Jacobi rotations
// (JacobiLanes.hpp), with the C library's logarithms one lane at a time (Eigen's vectorised
// logarithm differs from it in the last bits, and GCC 12 warns inside its AVX-512 code). Every
// path runs the same instructions on a point's lane, and which form a point takes depends on its
// own be only, so a point gives the same digits on every path (test: numericsTests "[lanes]").

#include "materials/plasticity/AxesFreeLaw.hpp"
#include "materials/plasticity/GatheredLanes.hpp"
#include "materials/plasticity/JacobiLanes.hpp"


namespace sph
{

template <int D, class Model>
template <int N>
void ReturnMapPlasticity<D, Model>::returnInLanes(const Mat<D>* F, const double* states,
                                                  std::size_t stride, std::size_t count, bool flow,
                                                  LanesWanted wanted, LanesResult<N>& out,
                                                  std::size_t componentStride) const
{
    static_assert(D == 2 || D == 3, "the bar (1D) has its own return");
    const GatheredLanes<D, N, State> in(F, states, stride, count, componentStride);
    Lane<N> be[D][D], finv[D][D];
    in.trialBe(be);
    in.inverse(finv);
    Lane<N> withoutAxes = Lane<N>::Zero();
    if (form_ == LawForm::series)
    {
        returnWithoutAxes<N>(in, be, finv, flow, wanted, out, withoutAxes);
        if (countLanes<N>([&](int i) { return withoutAxes[i] == 0.0; }) == 0)
        {
            return;
        }
    }
    // The points beyond the series' range (or every point, when asked): in principal axes.
    LanesResult<N> inAxes;
    returnInAxes<N>(in, be, finv, flow, wanted, inAxes);
    for (int i = 0; i < N; ++i)
    {
        if (withoutAxes[i] == 0.0)
        {
            out.copyLane(inAxes, i);
        }
    }
}

// §P12 (3D) and §P13 (2D): ε = ½ ln be without axes, the return on the tensor's volumetric part
// and deviator, τ = 2μ dev ε + p 1, exp(2ε) back. inRange[i] = 1 where lane i's result is valid
// (in 2D every lane). What differs between 2D and 3D is AxesFreeLaw<D>'s.
template <int D, class Model>
template <int N>
void ReturnMapPlasticity<D, Model>::returnWithoutAxes(const GatheredLanes<D, N, State>& in,
                                                      const Lane<N> (&be)[D][D],
                                                      const Lane<N> (&finv)[D][D], bool flow,
                                                      LanesWanted wanted, LanesResult<N>& out,
                                                      Lane<N>& inRange) const
{
    using Law = AxesFreeLaw<D>;
    constexpr int C = Law::components;
    StrainLanes<N, C> strain;
    Law::template strain<N>(in, be, strain, inRange);

    const DeviatorLanes<N, C> trial(strain);
    const bool changed = returnOrTrial<N, C>(strain, trial, in.alpha(), in.flowPressure(), flow,
                                             out.flow);

    // τ, P = τ F⁻ᵀ, W and the wave modulus M + max |τᵢ| (P2.5), from the returned strain's
    // parts: the trial's where no lane's strain changed (the same numbers from the same strain).
    DeviatorLanes<N, C> flowed; // (no std::optional: it would clear the lanes first)
    if (changed)
    {
        flowed.split(strain);
    }
    const DeviatorLanes<N, C>& returned = changed ? flowed : trial;
    Lane<N> tau[C];
    kirchhoffLanes<N, C>(returned, tau);
    constexpr int at[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
    lanes::multiplyLanes<N, D>([&](int k, int m) -> const Lane<N>& { return tau[at[k][m]]; },
                               [&](int m, int l) -> const Lane<N>& { return finv[l][m]; }, out.P);
    out.waveModulus = Lane<N>::Zero();
    if (wanted.waveModulus)
    {
        out.waveModulus = Law::template largestAbsolute<N>(tau);
        out.waveModulus += waveModulusLanes<N, C>(returned);
    }
    if (wanted.energy)
    {
        out.energy = elasticEnergyLanes<N, C>(returned);
        addExtraEnergy<N>(in.alpha(), out);
    }
    if (!wanted.next)
    {
        return;
    }
    const bool someFlow = countLanes<N>([&](int i) { return out.flow.deltaGamma[i] > 0.0; }) > 0;
    in.keepCommitted(out, someFlow);
    if (!someFlow)
    {
        return; // nothing flows: every state stays (each lane's result is its own either way)
    }
    Law::template writeFlowingStates<N, State>(returned, finv, out);
}

// §P4 in principal axes: the principal form of be, the return on the principal strains, τ
// assembled from them, exp of the returned strains.
template <int D, class Model>
template <int N>
void ReturnMapPlasticity<D, Model>::returnInAxes(const GatheredLanes<D, N, State>& in,
                                                 const Lane<N> (&be)[D][D],
                                                 const Lane<N> (&finv)[D][D], bool flow,
                                                 LanesWanted wanted, LanesResult<N>& out) const
{
    PrincipalLanes<N, D> principal;
    principalOf<N>(be, in.trialZZ(), principal);

    const DeviatorLanes<N> trial(principal.strain);
    const bool changed = returnOrTrial<N, 3>(principal.strain, trial, in.alpha(),
                                             in.flowPressure(), flow, out.flow);

    // τ, P = S F⁻ᵀ with S = Σ τₖ nₖ⊗nₖ, W and the wave modulus M + max |τ| (P2.5).
    const auto& v = principal.vectors;
    DeviatorLanes<N> flowed; // (no std::optional: it would clear the lanes first)
    if (changed)
    {
        flowed.split(principal.strain);
    }
    const DeviatorLanes<N>& returned = changed ? flowed : trial;
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
    out.waveModulus = Lane<N>::Zero();
    if (wanted.waveModulus)
    {
        const Lane<N> modulus = waveModulusLanes<N>(returned);
        for (int i = 0; i < N; ++i)
        {
            out.waveModulus[i] =
                modulus[i] +
                std::max(std::max(std::abs(tau[0][i]), std::abs(tau[1][i])), std::abs(tau[2][i]));
        }
    }
    if (wanted.energy)
    {
        out.energy = elasticEnergyLanes<N>(returned);
        addExtraEnergy<N>(in.alpha(), out);
    }
    if (!wanted.next)
    {
        return;
    }

    // The states to commit: where the point flows the returned be pulled back (§P4 step 4),
    // elsewhere the committed state.
    in.keepCommitted(out, true);
    for (int i = 0; i < N; ++i)
    {
        if (!(out.flow.deltaGamma[i] > 0.0))
        {
            continue;
        }
        const Eigen::Vector3d stretch = (2.0 * principal.strain.point(i)).array().exp();
        // B = Σ exp(2εₖ) nₖ⊗nₖ.
        double B[D][D];
        lanes::assemble<N, D>(v, i, stretch, B);
        lanes::writeFlowingState<D, N, State>(finv, B, stretch[2], out.flow, i, out.next);
    }
}

// The model's return of the trial strains (returned in place; `trial` their parts), or with
// flow = false the trial itself: no flow, α kept. Whether any lane's strain changed.
template <int D, class Model>
template <int N, int C>
bool ReturnMapPlasticity<D, Model>::returnOrTrial(StrainLanes<N, C>& strain,
                                                  const DeviatorLanes<N, C>& trial,
                                                  const Lane<N>& alpha, const Lane<N>& flowPressure,
                                                  bool flow, FlowLanes<N>& out) const
{
    out.pressure = Lane<N>::Constant(noFlowPressure);
    if (flow)
    {
        return model().template returnLanes<N, C>(strain, trial, alpha, flowPressure, out);
    }
    out.deltaGamma = Lane<N>::Zero();
    out.alpha = alpha;
    out.dissipation = Lane<N>::Zero();
    return false;
}

// W − Ψ(εe) where a point has flowed (now or before); without plastic flow the energy stays
// Hencky's.
template <int D, class Model>
template <int N>
void ReturnMapPlasticity<D, Model>::addExtraEnergy(const Lane<N>& alpha, LanesResult<N>& out) const
{
    if (countLanes<N>([&](int i) { return alpha[i] > 0.0 || out.flow.deltaGamma[i] > 0.0; }) == 0)
    {
        return; // the common case: a virgin point that stays elastic (one vector comparison)
    }
    for (int i = 0; i < N; ++i)
    {
        if (alpha[i] > 0.0 || out.flow.deltaGamma[i] > 0.0)
        {
            out.energy[i] += model().extraEnergy(
                Flow{out.flow.deltaGamma[i], out.flow.alpha[i], out.flow.dissipation[i]});
        }
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
