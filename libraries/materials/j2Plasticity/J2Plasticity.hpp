#pragma once
// `j2Plasticity`: finite-strain von Mises plasticity with linear isotropic hardening
// (docs/theory/plasticity.md): F = Fe Fp, Hencky elasticity on be = F Cp⁻¹ Fᵀ (§P2), the
// radial return in principal logarithmic strains (§P4, §P5):
//
//   q_tr = √(3/2) |s_tr|,  Φ = q − σy(α),  σy(α) = max(σy0 + H α, 0),
//   Δγ = (q_tr − σy0 − H α_n)/(3μ + H),  s = (1 − 3μΔγ/q_tr) s_tr,  α = α_n + Δγ;
//
// 2D plane strain (the zz component of Cp⁻¹ is history too), 1D a bar in uniaxial stress
// (§P6: τ = E (ln λ − εp), Δγ = (|τ_tr| − σy0 − H α_n)/(E + H)).
//
// Every stress is a trial return from the particle's committed state (HistoryOf); the state
// changes only in commit(), once per accepted level (§P7). Without yielding this is `hencky`
// to round-off. The energy evaluated is the incremental potential W = Ψ(εe) + Ψh(α) + σy0 Δγ
// (P4.2), of which the stress is the derivative; a commit dissipates σy0 Δγ per unit volume.
// All but the return itself is ReturnMapPlasticity's.
// Keys:
//   E, nu, rho        | as `hencky`
//   yieldStress       | initial yield stress σy0 [Pa], > 0                     | required
//   hardeningModulus  | H [Pa] (dσy/dα), > −3μ (1D: > −E); < 0 softens          | 0
// Fields (PlasticHistory.hpp): restart:inversePlasticCauchyGreen (Cp⁻¹; zz in 2D),
// restart:equivalentPlasticStrain (α committed), and for ParaView plasticStrain (α at the
// written level) and yielding (1 where the particle flows plastically at that level).

#include "materials/plasticity/ReturnMapPlasticity.hpp"
#include "materials/plasticity/ReturnLanes.hpp"

#include <type_traits>

namespace sph
{

template <int D>
class J2Plasticity : public ReturnMapPlasticity<D, J2Plasticity<D>>
{
public:
    using Flow = PlasticFlow;
    static std::string description();
    static Schema schema();
    J2Plasticity(const Params& params, const typename Material<D>::Args& args);

    double yieldStress(double alpha) const { return std::max(sigmaY0_ + H_ * alpha, 0.0); }
    // Ψh(α) = ∫₀^α (σy(a) − σy0) da
    double hardeningEnergy(double alpha) const;

    // The model's part of ReturnMapPlasticity: the radial return (§P5) in principal log
    // strains at N points side by side (ReturnLanes.hpp), the bar's return (§P6), W − Ψ(εe) = Ψh(α) + σy0 Δγ, and the commit's V0 σy0 Δγ.
    // Associative: its dissipation's book needs no flow pressure (plasticity.md (P9.7)).
    static constexpr bool keepsFlowPressure = false;
    template <int N, int C>
    bool returnLanes(StrainLanes<N, C>& eps, const DeviatorLanes<N, C>& trial, const Lane<N>& alpha,
                     const Lane<N>& flowPressure, FlowLanes<N>& flow) const;
    Flow returnUniaxial(double& eps, double alpha) const;
    double extraEnergy(const Flow& flow) const { return hardeningEnergy(flow.alpha) + flow.dissipation; }
    // This product order (V0 σy0 first) keeps the energy audit bit-identical to j2Plasticity
    // before ReturnMapPlasticity existed.
    double dissipated(double V0, const Flow& flow) const { return V0 * sigmaY0_ * flow.deltaGamma; }

private:
    // The flow of a return with multiplier Δγ from α_n.
    Flow flowOf(double deltaGamma, double alpha) const
    {
        return {deltaGamma, alpha + deltaGamma, sigmaY0_ * deltaGamma};
    }

    double sigmaY0_;
    double H_;
};

template <int D>
template <int N, int C>
bool J2Plasticity<D>::returnLanes(StrainLanes<N, C>& eps, const DeviatorLanes<N, C>& trial,
                                  const Lane<N>& alpha, const Lane<N>& /*flowPressure*/,
                                  FlowLanes<N>& flow) const
{
    const double mu = this->elastic_.mu;
    Lane<N> qTrials, yield;
    for (int i = 0; i < N; ++i)
    {
        qTrials[i] = std::sqrt(1.5) * 2.0 * mu * trial.norm[i];
        yield[i] = yieldStress(alpha[i]);
    }
    if (countLanes<N>([&](int i) { return qTrials[i] > yield[i]; }) == 0)
    {
        // Every lane inside the yield surface (most samples, most of the time): flowOf(0, α)
        // and eps kept, without the return's divisions.
        flow.deltaGamma = Lane<N>::Zero();
        flow.alpha = alpha + 0.0;
        flow.dissipation = sigmaY0_ * Lane<N>::Zero();
        return false;
    }
    // The return at every lane, in loops that each vectorise (one loop doing it all per lane
    // did not: three scalar divisions a lane, where most lanes of a yielding body flow).
    Lane<N> deltaGamma, shearScale, third;
    const auto radialReturn = [&](auto softening)
    {
        for (int i = 0; i < N; ++i)
        {
            const double qTrial = qTrials[i];
            const double hardened = (qTrial - sigmaY0_ - H_ * alpha[i]) / (3.0 * mu + H_);
            // Softening exhausted: σy = 0, s = 0. (Only where H < 0: with H ≥ 0 a lane that
            // flows has σy0 + H (α + Δγ) ≥ σy0 > 0, and a lane that does not keeps its strain
            // whatever it returned; so without softening the division is not computed.)
            const double returned =
                softening && sigmaY0_ + H_ * (alpha[i] + hardened) < 0.0 ? qTrial / (3.0 * mu)
                                                                          : hardened;
            shearScale[i] = 1.0 - 3.0 * mu * returned / qTrial;
            deltaGamma[i] = qTrial > yield[i] ? returned : 0.0;
            third[i] = trial.volumetric[i] / 3.0;
        }
    };
    if (H_ < 0.0)
    {
        radialReturn(std::true_type{});
    }
    else
    {
        radialReturn(std::false_type{});
    }
    for (int k = 0; k < C; ++k)
    {
        for (int i = 0; i < N; ++i)
        {
            const double scaled = trial.dev[k][i] * shearScale[i];
            const bool flows = qTrials[i] > yield[i];
            eps.eps[k][i] = flows ? (onDiagonal(k) ? scaled + third[i] : scaled) : eps.eps[k][i];
        }
    }
    for (int i = 0; i < N; ++i)
    {
        const Flow f = flowOf(deltaGamma[i], alpha[i]);
        flow.deltaGamma[i] = f.deltaGamma;
        flow.alpha[i] = f.alpha;
        flow.dissipation[i] = f.dissipation;
    }
    return true;
}

} // namespace sph
