#pragma once
// What every finite-strain plastic material of sphSolid shares (docs/theory/plasticity.md
// §P1–§P4, §P7): F = Fe Fp with Hencky elasticity on be = F Cp⁻¹ Fᵀ, the trial state and its
// principal log strains, the update of Cp⁻¹ from the returned strains, P = τ F⁻ᵀ, the
// evaluation from a particle's or a gradF sample's committed history (HistoryOf), the commit,
// the linearised correction, the wave-speed bound and the display fields. A model adds only
// what is its own, as non-virtual members of Model (CRTP: the return is inlined in the loops
// over sixteen points side by side, ReturnMapLanes.hpp, that every return runs through):
//
//   template <int N, int C> bool returnLanes(StrainLanes<N, C>& eps,
//       const DeviatorLanes<N, C>& trial, const Lane<N>& alpha, const Lane<N>& flowPressure,
//       FlowLanes<N>& flow) const;  2D/3D: the return at N points side by side
//       (ReturnLanes.hpp), on principal log strains (C = 3) or on the strain tensor (C = 6,
//       §P12–§P13: the law without principal axes); eps: trial in, returned out; trial: its
//       volumetric and deviatoric parts; alpha: the committed α; flowPressure: the committed
//       state's; returns whether any lane's eps changed (false: every lane inside the yield
//       surface, eps untouched — the common case, which should cost one comparison)
//   static constexpr bool keepsFlowPressure: whether the model sets flow.pressure (its
//       states then keep it, one number more in each compact state)
//   Flow returnUniaxial(double& eps, double alpha) const;            1D bar (only if the
//       model is registered in 1D)
//   double extraEnergy(const Flow& flow) const;   W − Ψ(εe) when the point has flowed (now or
//       before): the stored hardening energy plus the step's dissipation
//   double dissipated(double V0, const Flow& flow) const;  what a commit books, V0 ΔD
//   optional, over N points from their strains' volumetric and deviatoric parts (DeviatorLanes,
//       C components as above):
//       template <int N, int C> void kirchhoffLanesOf(e, Lane<N> (&tau)[C]) const,
//       template <int N, int C> Lane<N> elasticEnergyLanesOf(e) const and
//       template <int N, int C> Lane<N> waveModulusLanesOf(e) const: an elastic law of the
//       model's own in place of Hencky's (druckerPrager: no volumetric stress beyond its
//       tensile strength, §P9)
//
// Without plastic flow (now or before) the energy and the stress are `hencky`'s to round-off.
// The members are defined below and in the headers included at the end: ReturnMapLanes.hpp (the
// return in lanes), ReturnMapPaths.hpp (the evaluations through it), ReturnMapPoint.hpp (one
// point: returnMap, the linearised correction, the initial stress).

#include "materials/LogarithmicElasticity.hpp"
#include "materials/plasticity/PlasticHistory.hpp"
#include "materials/plasticity/LanesResult.hpp"
#include "materials/plasticity/ReturnLanes.hpp"
#include "materials/plasticity/ReturnMemo.hpp"

namespace sph
{

template <int D, int N, class State> struct GatheredLanes; // ReturnMapLanes.hpp

// Which form of the logarithmic law a return takes (docs/theory/plasticity.md §P12): the key
// `logarithm` of every return-map material.
enum class LawForm
{
    series,       // without principal axes: 3D where the series applies (in principal axes
                  // elsewhere), 2D everywhere in closed form (§P13)
    principalAxes // in principal axes everywhere (§P4: the law before §P12, for comparison)
};

template <int D, class Model>
class ReturnMapPlasticity : public Material<D>
{
public:
    using State = PlasticState<D>;
    using Flow = PlasticFlow;
    static std::vector<FieldSpec> fields() { return PlasticHistory<D>::fields(); }

    // The return map at one F from a committed state.
    struct Result
    {
        Mat<D> P;
        double energy = 0.0;    // W, e.g. (P4.2)
        Flow flow;              // flow.deltaGamma > 0: the point flows plastically
        double waveModulus = 0.0; // M + max |τᵢ| of the wave-speed bound (P2.5)
        State next;             // the state to commit (when asked for)
    };
    // flow = false: the trial state (the elastic predictor) only.
    Result returnMap(const Mat<D>& F, const State& committed, bool wantNext, bool flow = true) const;
    // The keys every return-map material shares (`logarithm`, §P12).
    static Schema lawSchema();
    double energy(const Mat<D>& F) const override { return returnMap(F, {}, false).energy; }
    Mat<D> stress(const Mat<D>& F) const override { return returnMap(F, {}, false).P; }
    double waveSpeed(const Mat<D>& F) const override
    {
        return waveSpeedOf(returnMap(F, State{}, false).waveModulus, F);
    }
    void evaluate(const Mat<D>* F, Mat<D>* P, double* psi, std::size_t n,
                  HistoryOf history) const override;
    double maxWaveSpeed(const Mat<D>* F, std::size_t n, std::size_t first) const override;
    double maxWaveSpeedSinceReference(const Mat<D>* F, const Mat<D>* Fr, std::size_t n,
                                      std::size_t first) const override;
    double youngsModulus() const override { return elastic_.E; }

    bool hasHistory() const override { return true; }
    bool readsStatesInRows() const override { return D >= 2; } // (the lanes' loads)
    // A = ∂(P − P_tr)/∂F by central differences of the return (step 1e-7 |F|).
    PlasticCorrection<D> plasticCorrection(const Mat<D>& F, std::size_t a) const override;
    double commit(const Mat<D>* F, const double* V0, std::size_t first, std::size_t n) override;
    State state(std::size_t a) const { return history_.state(a); }

    // An initial elastic strain: Cp⁻¹ = be = exp(2 εe) with εe = Hencky's inverse of sigma
    // (τ = σ at F = I), α = 0 (docs/theory/plasticity.md §P10).
    typename Material<D>::InitialStress startFromStress(std::size_t a,
                                                       const Eigen::Matrix3d& sigma) override;
    // ν/(1 − ν): no lateral strain, elastic (a model with friction overrides it).
    double atRestCoefficient() const override { return elastic_.nu / (1.0 - elastic_.nu); }

    std::size_t historyComponents() const override { return State::packedSize; }
    void packHistory(std::size_t a, double* out) const override { state(a).pack(out); }
    void packInitialHistory(double* out) const override { State{}.pack(out); }
    std::size_t compactHistoryComponents() const override
    {
        return State::compactSize(Model::keepsFlowPressure);
    }
    bool compactHistory(const double* packed, double* out) const override
    {
        return State::compact(packed, out, Model::keepsFlowPressure);
    }
    void expandHistory(const double* compact, double* out) const override
    {
        State::expand(compact, out, Model::keepsFlowPressure);
    }
    // (G4.1): Cp⁻¹ ← M Cp⁻¹ Mᵀ with M = to⁻¹ from, so that to Cp⁻¹ toᵀ = from Cp⁻¹ fromᵀ; the
    // zz component (plane strain: F_zz = 1 on both sides) and α are unchanged.
    void rebaseHistory(double* packed, const Mat<D>& from, const Mat<D>& to) const override
    {
        rebaseHistories(packed, State::packedSize, 1, &from, to);
    }
    // (to⁻¹ once for all of them: a particle's samples move to its one new frame.)
    void rebaseHistories(double* states, std::size_t stride, std::size_t count, const Mat<D>* from,
                         const Mat<D>& to) const override
    {
        const Mat<D> toInverse = to.inverse();
        for (std::size_t j = 0; j < count; ++j)
        {
            State s = State::unpack(states + j * stride);
            const Mat<D> M = toInverse * from[j];
            const Mat<D> Cp = M * s.inversePlastic * M.transpose();
            s.inversePlastic = 0.5 * (Cp + Cp.transpose());
            s.pack(states + j * stride);
        }
    }
    std::vector<std::string> rebasedFields() const override
    {
        return {PlasticHistory<D>::fields().front().name()}; // Cp⁻¹ (zz and α do not change)
    }
    void rebaseParticleHistory(std::size_t a, const Mat<D>& from, const Mat<D>& to) override
    {
        double packed[State::packedSize];
        state(a).pack(packed);
        rebaseHistory(packed, from, to);
        history_.store(a, State::unpack(packed));
    }

protected:
    ReturnMapPlasticity(const Params& params, const typename Material<D>::Args& args);

    IsotropicElasticity elastic_;
    HenckyLaw law_;
    LawForm form_;

private:
    const Model& model() const { return static_cast<const Model&>(*this); }
    // The elastic law at N points side by side, from the volumetric and deviatoric parts of
    // their principal log strains: the model's own, else Hencky's (P2.2),
    // τₖ = 2μ eₖ + K εv and Ψ = μ |e|² + ½ K εv².
    template <int N, int C> void kirchhoffLanes(const DeviatorLanes<N, C>& e, Lane<N> (&tau)[C]) const
    {
        if constexpr (requires(const Model& m) { m.template kirchhoffLanesOf<N, C>(e, tau); })
        {
            model().template kirchhoffLanesOf<N, C>(e, tau);
        }
        else
        {
            for (int k = 0; k < C; ++k)
            {
                for (int i = 0; i < N; ++i)
                {
                    tau[k][i] = onDiagonal(k) ? law_.kirchhoffOf(e.dev[k][i], e.volumetric[i])
                                              : law_.kirchhoffOf(e.dev[k][i], 0.0);
                }
            }
        }
    }
    template <int N, int C> Lane<N> elasticEnergyLanes(const DeviatorLanes<N, C>& e) const
    {
        if constexpr (requires(const Model& m) { m.template elasticEnergyLanesOf<N, C>(e); })
        {
            return model().template elasticEnergyLanesOf<N, C>(e);
        }
        else
        {
            Lane<N> energy;
            for (int i = 0; i < N; ++i)
            {
                energy[i] = law_.energyOf(e.squaredNorm(i), e.volumetric[i]);
            }
            return energy;
        }
    }
    // The modulus M of (P2.5) at the returned strains: the model's own (a material that has
    // opened carries no stress, P2.7), else the elastic longitudinal modulus.
    template <int N, int C> Lane<N> waveModulusLanes(const DeviatorLanes<N, C>& e) const
    {
        if constexpr (requires(const Model& m) { m.template waveModulusLanesOf<N, C>(e); })
        {
            return model().template waveModulusLanesOf<N, C>(e);
        }
        else
        {
            return Lane<N>::Constant(law_.longitudinalModulus());
        }
    }
    // (P2.5) with the stretch of `stretched` (F itself, or f = F Fr⁻¹ (P2.6)).
    // waveModulus: M + max |τ| of the return at F (particleReturn's, or returnMap's).
    double waveSpeedOf(double waveModulus, const Mat<D>& stretched) const;

    // The return map at N points side by side (ReturnMapLanes.hpp): returnMap's steps over
    // `count` ≤ N points with their committed states (stride apart); the lanes beyond
    // `count` are computed on the virgin state at F = I and ignored.
    template <int N>
    using LanesResult = sph::LanesResult<D, N>;
    template <int N>
    // (componentStride: 1, or the states in rows, HistoryOf::samplesInRows)
    void returnInLanes(const Mat<D>* F, const double* states, std::size_t stride, std::size_t count,
                       bool flow, LanesWanted wanted, LanesResult<N>& out,
                       std::size_t componentStride = 1) const;
    // Its two forms (§P12–§P13 and §P4) from the gathered points, their trial be and F⁻¹ (the
    // wave modulus and the energy only where asked: a gradF sample's wave modulus is never
    // read, nor its energy unless the energy is).
    template <int N>
    void returnWithoutAxes(const GatheredLanes<D, N, State>& in, const Lane<N> (&be)[D][D],
                           const Lane<N> (&finv)[D][D], bool flow, LanesWanted wanted,
                           LanesResult<N>& out, Lane<N>& inRange) const;
    template <int N>
    void returnInAxes(const GatheredLanes<D, N, State>& in, const Lane<N> (&be)[D][D],
                      const Lane<N> (&finv)[D][D], bool flow, LanesWanted wanted,
                      LanesResult<N>& out) const;
    template <int N, int C>
    bool returnOrTrial(StrainLanes<N, C>& strain, const DeviatorLanes<N, C>& trial,
                       const Lane<N>& alpha, const Lane<N>& flowPressure, bool flow,
                       FlowLanes<N>& out) const;
    template <int N> void addExtraEnergy(const Lane<N>& alpha, LanesResult<N>& out) const;
    // The principal form of N matrices be (in 2D with their zz components).
    template <int N>
    static void principalOf(const Lane<N> (&be)[D][D], const Lane<N>& beZZ, PrincipalLanes<N, D>& out);
    // evaluate's two paths, `lanes` points at a time from `first` (i in evaluate; F, P and psi
    // already offset, history's states from its first).
    void evaluateParticlesInLanes(const Mat<D>* F, Mat<D>* P, double* psi, std::size_t count,
                                  std::size_t firstParticle) const;
    template <std::size_t N>
    void evaluateSamplesInLanes(const Mat<D>* F, Mat<D>* P, double* psi, std::size_t count,
                                const HistoryOf& history, std::size_t first) const;
    // Two AVX-512 registers of doubles per quantity: the return is chains of divisions and
    // square roots that wait on each other, and two independent registers keep the units busy
    // (the rings' TL gradF row 16 % faster than with eight lanes, 3D within the noise;
    // docs/performance.md). The library is built without fused multiply-adds
    // (-ffp-contract=off, CMakeLists.txt), so that every width computes a lane alike; the 3D
    // series fuse explicitly, alike in every width (multiplyAdd, ReturnLanes.hpp).
    static constexpr std::size_t lanes = 16;

    // The memo of each particle's last return: the time step and the commit reuse the force
    // evaluation's (written by the one thread that evaluates the particle).
    typename ReturnMemo<D>::Entry particleReturn(std::size_t a, const Mat<D>& F, const State& s) const;
    // The same for the particles first, …, first + n − 1 (n ≤ lanes) at F[0 … n − 1]: those
    // the memo does not hold are computed together, in one set of lanes.
    void particleReturns(const Mat<D>* F, std::size_t first, std::size_t n,
                         typename ReturnMemo<D>::Entry* out) const;
    // visit(i, entry) for the particles first + i, i < n, at F[i], `lanes` at a time.
    template <class Visit>
    void visitParticleReturns(const Mat<D>* F, std::size_t first, std::size_t n, Visit visit) const
    {
        typename ReturnMemo<D>::Entry e[lanes];
        for (std::size_t i = 0; i < n; i += lanes)
        {
            const std::size_t count = std::min(lanes, n - i);
            particleReturns(F + i, first + i, count, e);
            for (std::size_t j = 0; j < count; ++j)
            {
                visit(i + j, e[j]);
            }
        }
    }

    PlasticHistory<D> history_;
    // Where the memo's fields go when the scheme never evaluates particles (gradF): an empty
    // registry of its own, so that it holds nothing and finds nothing (34 numbers per particle
    // less in 3D).
    ParticleFields<D> unusedMemoFields_;
    mutable ReturnMemo<D> memo_;
};

template <int D, class Model>
Schema ReturnMapPlasticity<D, Model>::lawSchema()
{
    return Schema().add(
        Key::word("logarithm",
                  "how the elastic strain 1/2 ln be is computed in 3D: series (by its series, "
                  "without principal axes, where the elastic shear strain is below about 2.5 %; "
                  "in principal axes elsewhere; in 2D in closed form without axes everywhere, "
                  "§P13) or principalAxes (always in principal axes, the "
                  "law before; the same results to round-off, slower); "
                  "docs/theory/plasticity.md §P12-§P13")
            .choices({"series", "principalAxes"})
            .defaultValue("series"));
}

template <int D, class Model>
ReturnMapPlasticity<D, Model>::ReturnMapPlasticity(const Params& params,
                                                   const typename Material<D>::Args& args)
    : Material<D>(params), elastic_(IsotropicElasticity::read<D>(params)), law_(elastic_),
      form_(params.word("logarithm") == "principalAxes" ? LawForm::principalAxes : LawForm::series),
      history_(args),
      memo_(args.particleEvaluations ? history_.registry() : unusedMemoFields_)
{
    if (args.F && args.fields)
    {
        // What ParaView shows at a level: the return at that level's F, not yet committed (§P7).
        const std::vector<Mat<D>>* F = args.F;
        args.fields->template deriveOver<double>(
            PlasticHistory<D>::plasticStrainField(), args.particles.begin, args.particles.end,
            [this, F](std::size_t a) { return particleReturn(a, (*F)[a], state(a)).flow.alpha; });
        args.fields->template deriveOver<int>(
            PlasticHistory<D>::yieldingField(), args.particles.begin, args.particles.end,
            [this, F](std::size_t a)
            { return particleReturn(a, (*F)[a], state(a)).flow.deltaGamma > 0.0 ? 1 : 0; });
    }
}

template <int D, class Model>
typename ReturnMemo<D>::Entry ReturnMapPlasticity<D, Model>::particleReturn(std::size_t a,
                                                                           const Mat<D>& F,
                                                                           const State& s) const
{
    typename ReturnMemo<D>::Entry e;
    if (!memo_.find(a, F, s, e))
    {
        const Result r = returnMap(F, s, true);
        e = {r.waveModulus, r.flow, r.next};
    }
    return e;
}

template <int D, class Model>
double ReturnMapPlasticity<D, Model>::waveSpeedOf(double waveModulus, const Mat<D>& stretched) const
{
    // (P2.5): the elastic modulus bounds the elastoplastic one; the stretch sets the scale.
    const double lowest = stretchSquaredRange<D>(stretched).first;
    return std::sqrt(waveModulus / lowest / this->density());
}

template <int D, class Model>
double ReturnMapPlasticity<D, Model>::maxWaveSpeedSinceReference(const Mat<D>* F, const Mat<D>* Fr,
                                                                 std::size_t n,
                                                                 std::size_t first) const
{
    double c = 0.0;
    visitParticleReturns(F, first, n, [&](std::size_t i, const auto& e)
                         { c = std::max(c, waveSpeedOf(e.waveModulus, Mat<D>(F[i] * Fr[i].inverse()))); });
    return c;
}

template <int D, class Model>
double ReturnMapPlasticity<D, Model>::maxWaveSpeed(const Mat<D>* F, std::size_t n,
                                                   std::size_t first) const
{
    double c = 0.0;
    visitParticleReturns(F, first, n, [&](std::size_t i, const auto& e)
                         { c = std::max(c, waveSpeedOf(e.waveModulus, F[i])); });
    return c;
}

template <int D, class Model>
double ReturnMapPlasticity<D, Model>::commit(const Mat<D>* F, const double* V0, std::size_t first,
                                             std::size_t n)
{
    double dissipated = 0.0;
    visitParticleReturns(F, first, n,
                         [&](std::size_t i, const auto& e)
                         {
                             if (e.flow.deltaGamma > 0.0)
                             {
                                 history_.store(first + i, e.next);
                                 dissipated += model().dissipated(V0[i], e.flow);
                             }
                             else
                             {
                                 history_.forgetFlowPressure(first + i); // the flow has stopped
                             }
                         });
    return dissipated;
}

} // namespace sph

#include "materials/plasticity/ReturnMapLanes.hpp"
#include "materials/plasticity/ReturnMapPaths.hpp"
#include "materials/plasticity/ReturnMapPoint.hpp"
