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
// to the bit. The energy evaluated is the incremental potential W = Ψ(εe) + Ψh(α) + σy0 Δγ
// (P4.2), of which the stress is the derivative; a commit dissipates σy0 Δγ per unit volume.
// Keys:
//   E, nu, rho        | as `hencky`
//   yieldStress       | initial yield stress σy0 [Pa], > 0                     | required
//   hardeningModulus  | H [Pa] (dσy/dα), > −3μ (1D: > −E); < 0 softens          | 0
// Fields: restart:inversePlasticCauchyGreen (Cp⁻¹; zz in 2D), restart:equivalentPlasticStrain
// (α committed), and for ParaView plasticStrain (α at the written level) and yielding (1 where
// the particle flows plastically at that level).

#include "materials/LogarithmicElasticity.hpp"
#include "materials/Material.hpp"

#include <memory>

namespace sph
{

template <int D>
class J2Plasticity : public Material<D>
{
public:
    static std::string description();
    static Schema schema();
    static std::vector<FieldSpec> fields();
    J2Plasticity(const Params& params, const typename Material<D>::Args& args);

    // A particle's committed history (§P1): Cp⁻¹ (its in-plane block; zz separately in 2D; in
    // 1D exp(−2 εp)) and the equivalent plastic strain α.
    struct State
    {
        Mat<D> inversePlastic = Mat<D>::Identity();
        double inversePlasticZZ = 1.0;
        double alpha = 0.0;
    };
    // The return map at one F from a committed state.
    struct Result
    {
        Mat<D> P;
        double energy = 0.0;     // W of (P4.2)
        double deltaGamma = 0.0; // > 0: the point flows plastically
        double maxAbsTau = 0.0;  // max |τᵢ| (for the wave-speed bound)
        State next;              // the state to commit (when asked for)
    };
    // flow = false: the trial state (the elastic predictor) only.
    Result returnMap(const Mat<D>& F, const State& committed, bool wantNext,
                     bool flow = true) const;
    double yieldStress(double alpha) const { return std::max(sigmaY0_ + H_ * alpha, 0.0); }
    // Ψh(α) = ∫₀^α (σy(a) − σy0) da
    double hardeningEnergy(double alpha) const;

    double energy(const Mat<D>& F) const override { return returnMap(F, {}, false).energy; }
    Mat<D> stress(const Mat<D>& F) const override { return returnMap(F, {}, false).P; }
    double waveSpeed(const Mat<D>& F) const override { return waveSpeedOf(F, State{}); }
    void evaluate(const Mat<D>* F, Mat<D>* P, double* psi, std::size_t n,
                  HistoryOf history) const override;
    double maxWaveSpeed(const Mat<D>* F, std::size_t n, std::size_t first) const override;
    double youngsModulus() const override { return elastic_.E; }

    bool hasHistory() const override { return true; }
    // A = ∂(P − P_tr)/∂F by central differences of the closed-form return (step 1e-7 |F|).
    PlasticCorrection<D> plasticCorrection(const Mat<D>& F, std::size_t a) const override;
    double commit(const Mat<D>* F, const double* V0, std::size_t first, std::size_t n) override;
    State state(std::size_t a) const;

    // A state as numbers: Cp⁻¹ (D×D, row-major), then Cp⁻¹_zz (2D), then α.
    static constexpr std::size_t packedSize = D * D + (D == 2 ? 1 : 0) + 1;
    std::size_t historyComponents() const override { return packedSize; }
    void packHistory(std::size_t a, double* out) const override { pack(state(a), out); }
    static void pack(const State& s, double* out);
    static State unpack(const double* in);

private:
    double waveSpeedOf(const Mat<D>& F, const State& state) const;
    // The return in principal log strains (§P5); eps in, returned eps out.
    double radialReturn(Eigen::Vector3d& eps, double alpha) const;

    IsotropicElasticity elastic_;
    HenckyLaw law_;
    double sigmaY0_;
    double H_;
    // The history, in the registry (or owned here when the material is built alone).
    std::unique_ptr<ParticleFields<D>> ownFields_;
    std::vector<Mat<D>>* inversePlastic_ = nullptr;
    std::vector<double>* inversePlasticZZ_ = nullptr; // 2D only
    std::vector<double>* alpha_ = nullptr;
};

} // namespace sph
