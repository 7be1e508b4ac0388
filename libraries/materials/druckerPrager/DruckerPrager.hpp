#pragma once
// `druckerPrager`: finite-strain Drucker–Prager plasticity of a frictional material (soil,
// sand), perfectly plastic, non-associated, with a tension cut-off (docs/theory/plasticity.md
// §P9). F = Fe Fp and Hencky elasticity on be = F Cp⁻¹ Fᵀ as j2Plasticity (§P1–§P4, §P7: all
// of that is ReturnMapPlasticity's); the return in principal log strains is its own:
//
//   p = tr τ/3 (tension > 0), √J2 = |dev τ|/√2,
//   Φ = √J2 + η p − ξ c,   G = √J2 + η̄ p                                  (P9.1)
//   the tension cut-off is in the elastic law: p = min(K εv, σt) (P9.5), so volumetric
//   strain beyond εt = σt/K opens voids that close again without stress (granular matter
//   pulled apart, then pressed together);
//   cone: Δγ = Φ_tr/(μ + K η η̄), s = (1 − μΔγ/√J2_tr) s_tr, εv = εv_tr − η̄ Δγ while
//   εv ≤ εt; Δγ = Φ_tr/μ at p = σt while εv ≥ εt (P9.3) (with the default σt = ξ c/η the
//   capped branch is the apex: s = 0).
//
// η, ξ from φ and η̄ from ψ by the cone's matching to Mohr–Coulomb (planeStrain: Bui et al.
// 2008; planeStrainFlow: the same at the material's ψ, (P9.6); outer/inner: de Souza Neto et
// al. 2008 §8.2.4). ψ = 0: no plastic volume change on
// the cone; ψ = φ: associative. The energy is W = Ψ(εe) + τ:Δεp (P9.4), the step's plastic
// work being what a commit dissipates; without yielding this is `hencky` to round-off. With
// ψ ≠ φ the stress is not ∂W/∂F (no incremental potential), and the step's plastic work is
// booked by the trapezoid from the pressure of the last flowing commit, the state's flow
// pressure: W = Ψ(εe) + τ:Δεp + ½ (η̄ − η) Δγ (p_c − p) (P9.7). α (output only):
// α += √(2/3)|dev Δεp|. 2D plane strain and 3D only (registered so: a 1D case is told so).
// Keys:
//   E, nu, rho       | as `hencky`
//   frictionAngle    | φ [degrees], in (0, 90)                                    | required
//   cohesion         | c [Pa], ≥ 0                                               | 0
//   dilatancyAngle   | ψ [degrees], in [0, φ]                                     | 0
//   tensileStrength  | σt [Pa], in [0, ξ c/η] (the cone's apex pressure)          | ξ c/η
//   coneMatching     | planeStrain | planeStrainFlow | outer | inner             | planeStrain
// Fields: those of j2Plasticity (PlasticHistory.hpp).

#include "materials/plasticity/ReturnLanes.hpp"
#include "materials/plasticity/ReturnMapPlasticity.hpp"

namespace sph
{

// The cone's η, ξ and η̄ matched to Mohr–Coulomb of friction angle φ and dilatancy angle ψ
// [radians] (plasticity.md §P9): planeStrain, outer and inner take η, ξ from φ and η̄ the same
// way from ψ; planeStrainFlow takes all three from both, so that steady plane-strain flow at
// that ψ meets Mohr–Coulomb of angle φ (planeStrain is the case ψ = φ).
struct ConeMatching
{
    enum class Kind
    {
        planeStrain,
        planeStrainFlow,
        outer,
        inner
    };
    struct Cone
    {
        double eta;
        double xi;
        double etaBar;
    };
    static std::vector<std::string> names()
    {
        return {"planeStrain", "planeStrainFlow", "outer", "inner"};
    }
    static Kind parse(const std::string& name);
    static Cone of(Kind kind, double phi, double psi);
    // ξ c/η: the largest mean stress (tension) on the cone.
    static double apexPressure(Kind kind, double phi, double psi, double cohesion);
};

// The strength a factor F leaves (docs/theory/geotechnics.md (E2.1)), angles in radians:
// tan φ_F = tan φ / F, c_F = c / F, ψ_F = min(ψ, φ_F) (the flow may not dilate more than the
// reduced soil's friction allows).
struct ReducedStrength
{
    double frictionAngle;
    double dilatancyAngle;
    double cohesion;
    static ReducedStrength of(double phi, double psi, double cohesion, double factor);
};

template <int D> class DruckerPrager : public ReturnMapPlasticity<D, DruckerPrager<D>>
{
public:
    using Flow = PlasticFlow;
    static std::string description();
    static Schema schema();
    DruckerPrager(const Params& params, const typename Material<D>::Args& args);

    // The model's part of ReturnMapPlasticity (§P9): the cone/cut-off return in principal log
    // strains at N points side by side (ReturnLanes.hpp), W − Ψ(εe) = τ:Δεp, and the commit's
    // V0 τ:Δεp.
    // Its states keep the pressure of their last flowing commit (used where ψ ≠ φ, (P9.7)).
    static constexpr bool keepsFlowPressure = true;
    template <int N, int C>
    bool returnLanes(StrainLanes<N, C>& eps, const DeviatorLanes<N, C>& trial, const Lane<N>& alpha,
                     const Lane<N>& flowPressure, FlowLanes<N>& flow) const;
    // The elastic law with the tension cut-off in it (P9.5), at N points: Hencky's, but the
    // volumetric stress p = min(K εv, σt): strain beyond σt/K opens voids that close again
    // without stress.
    template <int N, int C> void kirchhoffLanesOf(const DeviatorLanes<N, C>& e, Lane<N> (&tau)[C]) const
    {
        for (int k = 0; k < C; ++k)
        {
            for (int i = 0; i < N; ++i)
            {
                tau[k][i] = onDiagonal(k) ? 2.0 * this->law_.mu * e.dev[k][i] +
                                                std::min(this->law_.K * e.volumetric[i], tensileStrength_)
                                          : 2.0 * this->law_.mu * e.dev[k][i];
            }
        }
    }
    template <int N, int C> Lane<N> elasticEnergyLanesOf(const DeviatorLanes<N, C>& e) const
    {
        const double K = this->law_.K;
        const double opening = tensileStrength_ / K; // εt
        Lane<N> energy;
        for (int i = 0; i < N; ++i)
        {
            const double ev = e.volumetric[i];
            const double volumetric =
                ev <= opening ? 0.5 * K * ev * ev : tensileStrength_ * (ev - 0.5 * opening);
            energy[i] = this->law_.mu * e.squaredNorm(i) + volumetric;
        }
        return energy;
    }
    // The modulus of the wave-speed bound (plasticity.md (P2.7)) at the returned strains: where
    // the voids are open (εv > εt) the pressure does not change with εv, so only the shear
    // modulus acts, and not even that at the apex of a cohesionless cone, where every
    // admissible state is stress-free; elsewhere the elastic M = K + 4μ/3.
    template <int N, int C> Lane<N> waveModulusLanesOf(const DeviatorLanes<N, C>& e) const
    {
        const double open =
            xi_ * cohesion_ - eta_ * tensileStrength_ > 0.0 ? 4.0 * this->law_.mu / 3.0 : 0.0;
        const double opening = tensileStrength_ / this->law_.K;
        Lane<N> modulus;
        for (int i = 0; i < N; ++i)
        {
            modulus[i] = e.volumetric[i] > opening ? open : this->law_.longitudinalModulus();
        }
        return modulus;
    }
    double extraEnergy(const Flow& flow) const { return flow.dissipation; }
    double dissipated(double V0, const Flow& flow) const { return V0 * flow.dissipation; }

    double apexPressure() const { return apexPressure_; }
    // Opened (Material::opened): without a tension cut-off (σt = 0) a point whose
    // εv = ½ ln det be > 0 has open voids, p = 0, and (returned) sits at the cone's apex.
    bool opened(const double* packed, const Mat<D>& F) const override
    {
        if (tensileStrength_ != 0.0)
        {
            return false;
        }
        const auto state = PlasticState<D>::unpack(packed);
        const double J = F.determinant();
        double detBe = J * J * state.inversePlastic.determinant();
        if constexpr (D == 2)
        {
            detBe *= state.inversePlasticZZ;
        }
        return detBe > 1.0;
    }
    // Jaky's K0 = 1 − sin φ for a frictional material at rest (§P10).
    double atRestCoefficient() const override { return atRest_; }

private:
    // The cone of the reduced strength (strengthReduction F, ReducedStrength; F = 1 by default)
    double eta_;          // η of φ_F
    double xi_;           // ξ of φ_F
    double etaBar_;       // η̄ of ψ_F
    double cohesion_;     // c/F
    double apexPressure_; // ξ c/η
    double tensileStrength_; // σt/F
    double atRest_;       // 1 − sin φ_F
};

template <int D>
template <int N, int C>
bool DruckerPrager<D>::returnLanes(StrainLanes<N, C>& eps, const DeviatorLanes<N, C>& trial,
                                   const Lane<N>& alpha, const Lane<N>& flowPressure,
                                   FlowLanes<N>& flow) const
{
    const double K = this->law_.K;
    const double mu = this->law_.mu;
    const double opening = tensileStrength_ / K; // εt: beyond it the voids open (P9.5)
    // Each loop over the lanes vectorises: both branches computed, one kept per lane.
    Lane<N> phiTrial, rootJ2Trials, evReturned, shearScale, deltaGamma;
    for (int i = 0; i < N; ++i)
    {
        const double ev = trial.volumetric[i];
        rootJ2Trials[i] = std::sqrt(2.0) * mu * trial.norm[i]; // √J2 = |s|/√2, s = 2μ dev ε
        phiTrial[i] = rootJ2Trials[i] + eta_ * std::min(K * ev, tensileStrength_) - xi_ * cohesion_;
    }
    if (countLanes<N>([&](int i) { return phiTrial[i] > 0.0; }) == 0)
    {
        // Every lane inside the cone (most samples, most of the time): no flow, eps kept.
        flow.deltaGamma = Lane<N>::Zero();
        flow.alpha = alpha;
        flow.dissipation = Lane<N>::Zero();
        flow.pressure = Lane<N>::Constant(noFlowPressure);
        return false;
    }
    for (int i = 0; i < N; ++i)
    {
        const double ev = trial.volumetric[i];
        const double rootJ2Trial = rootJ2Trials[i];
        // (P9.3) On the capped branch p = σt does not change with εv: the cone alone returns
        // s; accepted while the dilatancy keeps εv ≥ εt. Else (or from εv_tr ≤ εt) the linear
        // branch.
        const double cappedGamma = phiTrial[i] / mu;
        const double cappedEv = ev - etaBar_ * cappedGamma;
        const double linearGamma =
            (rootJ2Trial + eta_ * K * ev - xi_ * cohesion_) / (mu + K * eta_ * etaBar_);
        const bool capped = (ev > opening) & (cappedEv >= opening);
        deltaGamma[i] = capped ? cappedGamma : linearGamma;
        evReturned[i] = capped ? cappedEv : ev - etaBar_ * linearGamma;
        // √J2 = ξc − η p ≥ 0 after the return, since p ≤ σt ≤ ξ c/η.
        shearScale[i] = std::max(1.0 - mu * deltaGamma[i] / rootJ2Trial, 0.0);
    }
    // τ:Δεp = s:Δe + p Δεv (P9.4), and α += √(2/3)|dev Δεp| (a tensor's off-diagonal
    // components twice). (The diagonal and the off-diagonal components in loops of their own:
    // with the choice inside the loop over the lanes GCC left it scalar, a third of the
    // rings' step in TL gradF.)
    Lane<N> work = Lane<N>::Zero();
    Lane<N> plasticNorm = Lane<N>::Zero();
    const Lane<N> evThird = evReturned / 3.0; // (as an array: one vector division)
    for (int k = 0; k < C; ++k)
    {
        const double twice = onDiagonal(k) ? 1.0 : 2.0; // 1.0 × x is x, to the bit
        const Lane<N> devReturned = shearScale * trial.dev[k];
        const Lane<N> plastic = trial.dev[k] - devReturned;
        work += twice * (devReturned * plastic);
        plasticNorm += twice * (plastic * plastic);
        for (int i = 0; i < N; ++i)
        {
            const double returned =
                onDiagonal(k) ? devReturned[i] + evThird[i] : devReturned[i];
            eps.eps[k][i] = phiTrial[i] > 0.0 ? returned : eps.eps[k][i];
        }
    }
    // (P9.7): where ψ ≠ φ the step's τ:Δεp is the right end of ∫ τ:dεp, which on the cone
    // differs from the work the forces did by (η̄ − η) ∫ Δγ dp; the trapezoid from the last
    // flowing commit's pressure p_c closes it to second order. At the start of a flow (no p_c)
    // the right end is kept.
    const bool nonAssociative = etaBar_ != eta_;
    // (Into locals, copied out at the end: `flow` may hold `alpha` or `flowPressure` for all
    // the compiler knows, and writing it in the loop kept the loop scalar.)
    Lane<N> nextDeltaGamma, nextAlphas, dissipation, pressure;
    for (int i = 0; i < N; ++i)
    {
        const double p = std::min(K * evReturned[i], tensileStrength_);
        const double rightEnd = 2.0 * mu * work[i] + p * (trial.volumetric[i] - evReturned[i]);
        // (`&`, not `&&`: no branch in the loop, which then vectorises.)
        const bool trapezoid = nonAssociative & (flowPressure[i] != noFlowPressure);
        const double correction =
            trapezoid ? 0.5 * (etaBar_ - eta_) * deltaGamma[i] * (flowPressure[i] - p) : 0.0;
        const double nextAlpha = alpha[i] + std::sqrt(2.0 / 3.0) * std::sqrt(plasticNorm[i]);
        const bool flows = phiTrial[i] > 0.0;
        nextDeltaGamma[i] = flows ? deltaGamma[i] : 0.0;
        nextAlphas[i] = flows ? nextAlpha : alpha[i];
        dissipation[i] = flows ? rightEnd + correction : 0.0;
        pressure[i] = flows & nonAssociative ? p : noFlowPressure;
    }
    flow.deltaGamma = nextDeltaGamma;
    flow.alpha = nextAlphas;
    flow.dissipation = dissipation;
    flow.pressure = pressure;
    return true;
}

} // namespace sph
