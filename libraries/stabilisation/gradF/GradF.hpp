#pragma once
// `gradF`: the seed paper's method (Saito & Kusachi 2017, §2.6), normative form spec §6.
// No tuning parameter.
//
// Kinematics: F_b(a) = F_a + G_a x^r_ba ("F at b seen from a", eq. 21), G_a = ∇_{x^r} F_a =
//   H_a F^r_a + f_a K_a, H_a = ∇_{x^r} f_a from a weighted least-squares fit of the second-
//   order Taylor term with f_a fixed (monomials v_j v_k, j <= k: 1, 3, 6 unknowns in 1D/2D/3D),
//   weights Ŵ_ab = W_ab V^r_b / Σ_e W_ae V^r_e (spec §6.2), and K = ∂F^r/∂x^r carried across
//   reference updates (K ← G f^{-1}, spec §6.5).
// Energy: Π = Σ_a V0_a Σ_{b∈N(a)} Ŵ_ab Ψ(F_b(a)) (spec §6.3).
// Force: the exact -∂Π/∂x of spec §6.4 (which replaces the paper's garbled eq. 33):
//   T_c = -Σ_a V0_a { (A_a - C_a Y_a) g_a(c) + C_a (Ŵ_ac z_ac - δ_ac s_a) }.
// Without the gradient term (G = 0) this is exactly `none`.
// A material with history (docs/theory/plasticity.md §P7), two evaluations of the samples:
//   ownHistory  every sample keeps its own (SampleHistory), trial return at each sample; the
//               commit dissipates Σ_a V0_a Σ_b Ŵ_ab D(F_b(a)); force = −∂Π/∂x (the default)
//   linearised  trial stresses from a's history plus the return's correction at F_a,
//               linearised with its tangent (evaluation 2, for comparison: not an energy
//               gradient); the particles commit at F_a as with `none`
//   elasticState updated Lagrangian in plastic flow (docs/theory/gradF-plastic.md): the
//               particles with history carry no K (G_a = H_a F^r_a, the gradient of the
//               increment since the move) and their F^r is the dilation J^(1/D) I (G2.4);
//               each sample keeps its own state, rebased at every move so that its elastic be
//               does not change (G4.1); a new pair starts from its neighbour's state. Total
//               Lagrangian (§G25-§G26): each particle's frame (F and x of the last commit,
//               SampleFrames.hpp) moves at every commit, the samples extrapolate the step's
//               increment, its gradient fitted in the frame as `fit` says (G26.1-G26.4), and
//               their states are rebased there as at a move.
// Sample volume (docs/theory/gradF-plastic.md §G13):
//   own       each sample's own det F_b(a) (the paper)
//   particle  every sample of a takes a's volume: F̄_b(a) = (J_a / det F_b(a))^(1/D) F_b(a), the
//             F-bar method; the spread of the samples is then isochoric and the force the exact
//             −∂Π/∂x of the energy at F̄ (§G13: the deviatoric Kirchhoff stress of each sample
//             through its own F_b, their mean pressure through F_a). Only for the particles of
//             a material with history (plastic): an elastic body keeps the paper's samples, bit
//             for bit (§G14: with F-bar the UL twisting column fails)
// Fit (docs/theory/gradF-plastic.md §G17):
//   sequential  f_a the corrected gradient, then H_a by least squares with f_a fixed (the paper)
//   joint       f_a and H_a from one weighted least-squares fit of the second-order Taylor
//               expansion, [f_a | c_a] = Σ_b Ŵ_ab x_ba ⊗ p_ab A_a⁻¹ (G17.2): the samples exact
//               for quadratic motions at free surfaces and on disordered clouds too; force
//               (G17.3), the exact −∂Π/∂x
// Keys:
//   plasticSamples | ownHistory | linearised | elasticState | ownHistory
//   sampleVolume   | own | particle                           | own
//   fit            | sequential | joint                       | sequential
//   samplePoints   | neighbours | moments                     | neighbours
// Sample points (docs/theory/gradF-moments.md):
//   neighbours  a sample at every neighbour b, F_b(a) (the paper)
//   moments     2D + 1 points with the kernel weights' moments of order 0, 1 and 2: the same
//               energy for every Ψ quadratic in F, about 6x (2D) and 8x (3D) fewer stress
//               evaluations; the particle is point 0. Total Lagrangian with any material
//               (ownHistory or linearised); updated Lagrangian without history, or with
//               plasticSamples elasticState, whose points turn with the material at each move
//               and carry their states (§M7)

#include "stabilisation/CsphOperators.hpp"
#include "stabilisation/gradF/MomentSamples.hpp"
#include "stabilisation/gradF/SampleFrames.hpp"
#include "stabilisation/gradF/SampleHistory.hpp"

namespace sph
{

template <int D>
class GradF : public Stabilisation<D>
{
public:
    static constexpr int M = monomialCount<D>;
    static constexpr int P = D + M; // fit joint: the linear and quadratic unknowns together
    using MatM = Eigen::Matrix<double, M, M>;
    using MatP = Eigen::Matrix<double, P, P>;
    using MatDP = Eigen::Matrix<double, D, P>;
    using MatDM = Eigen::Matrix<double, D, M>;
    using MatMD = Eigen::Matrix<double, M, D>;

    static std::string description();
    static Schema schema();
    GradF(const Params& params, const typename Stabilisation<D>::Args&);

    ReferenceNeeds referenceNeeds(const Kernel& kernel) const override
    {
        return {kernel.supportRadius(), true, true};
    }
    ForceStatus prepare(const ReferenceConfiguration<D>& ref) override;
    ForceStatus referenceUpdate(const std::vector<Vec<D>>& x, const ReferenceConfiguration<D>& ref,
                                std::vector<Mat<D>>& F,
                                std::vector<Tensor3<D>>* newK) const override;
    Mat<D> deformationGradient(std::size_t a, const std::vector<Vec<D>>& x,
                               const ReferenceConfiguration<D>& ref) const override;
    ForceStatus computeForces(const ForceInput<D>& in, ForceOutput<D>& out,
                              bool wantEnergy) override;
    double energy(const ForceInput<D>& in) override;
    void declareHistory(const std::vector<const Material<D>*>& materials,
                        ParticleFields<D>& fields) override
    {
        refuseMovingMomentHistory(materials);
        if (!linearised_)
        {
            // Updated Lagrangian with moment points: a particle's samples are its points,
            // whatever its neighbours, and the points follow the material (§M7).
            const bool points = moments_.active() && elasticState_ && referenceMoves_;
            samples_.declare(materials, fields, weights_ != MoveWeights::kernel,
                             points ? MomentPoints<D>::count : 0);
            if (points && samples_.active())
            {
                moments_.carryStates(fields);
            }
        }
        if (elasticState_ && !referenceMoves_)
        {
            frames_.declare(fields); // §G25
        }
    }
    void moveHistory(const std::vector<Vec<D>>& x, const ReferenceConfiguration<D>& ref,
                     const std::vector<int>& body,
                     const std::vector<Material<D>*>& materials) override;
    double commitHistory(const HistoryCommit<D>& in) override;
    // What the commit reads of an evaluation besides F and P: the samples' pending states and
    // their dissipation (the materials' own return memo is found again or recomputed, to the
    // same digits).
    bool setAsideEvaluation() override
    {
        samples_.setAsidePending();
        frames_.setAside();
        dissipationAside_.swap(sampleDissipation_);
        return true;
    }
    void restoreEvaluation() override
    {
        samples_.restorePending();
        frames_.restore();
        dissipationAside_.swap(sampleDissipation_);
    }
    bool movesParticleHistory() const override { return elasticState_; }
    // A material with history is evaluated at the stress samples (its own history each, or the
    // particle's trial with `plasticSamples linearised`), never through a particle's memo.
    bool evaluatesParticles() const override { return false; }
    bool movesDissipate() const override { return openedFromParticle_; }
    double moveDissipation(const std::vector<std::uint8_t>* owned) const override;
    std::string nextToTry(bool updated, bool plastic) const override
    {
        if (updated && plastic && !elasticState_)
        {
            return "plasticSamples elasticState in stabilisation (updated Lagrangian in plastic "
                   "flow, docs/theory/gradF-plastic.md), or formulation totalLagrangian";
        }
        return updated ? "formulation totalLagrangian" : "";
    }

    // Whether particles' moment points are evaluated in groups (sampleGroup; on by default;
    // public for the test that grouping changes no digit).
    void groupSampleEvaluations(bool on) { groupSamples_ = on; }

    // Kinematics of particle a at positions x: f_a, F_a = f_a F^r_a and G_a (public for tests).
    struct Kinematics
    {
        Mat<D> f;
        Mat<D> F;
        Tensor3<D> G;
        Tensor3<D> H; // ∇_{x^r} f
    };
    Kinematics kinematics(std::size_t a, const std::vector<Vec<D>>& x,
                          const ReferenceConfiguration<D>& ref) const;

    // Per-neighbour quantities of one particle, computed once and reused by every loop.
    struct Scratch
    {
        std::vector<Vec<D>> xr; // x^r_ba
        std::vector<double> w;  // Ŵ_ab
        std::vector<Mat<D>> F;  // F_b(a)
        std::vector<Mat<D>> P;  // P(F_b(a))
        std::vector<double> psi;
        std::vector<double> dissipation; // per unit initial volume, by a commit at F_b(a)
        std::vector<double> omega;       // energy weights chosen at a move (§G9)
        std::vector<double> states;      // the samples' committed states, unpacked (§P7)
        std::vector<double> nextStates;  // and the states a commit would make of them
        std::vector<std::uint8_t> changed; // (HistoryOf::changed) which of them were written
        std::vector<double> alpha;       // sampleVolume particle: (J_a / det F_b(a))^(1/D)
        // Total-Lagrangian elasticState (§G26): the fit of the step's increment in the frame,
        // what its force (G26.3) takes of it.
        struct FrameFit
        {
            MatM Zinv;          // Z°_a⁻¹, regularised as the paper's Z_a⁻¹
            MatMD Y;            // Y°_a = Σ_b Ŵ_ab z(y°_ab) ⊗ y°_ab
            MonomialVec<D> s;   // s°_a = Σ_b Ŵ_ab z(y°_ab)
            Mat<D> inverseFrameF; // F°_a⁻¹
            Tensor3<D> H;       // H°_a of (G26.2)
            MatP Ainv;          // fit joint: A°_a⁻¹ of (G26.4)
            Vec<D> moment;      // fit joint: Σ_b Ŵ_ab y°_ab
        } frame;
        void resize(std::size_t n)
        {
            alpha.resize(n);
            omega.resize(n);
            dissipation.resize(n);
            xr.resize(n);
            w.resize(n);
            F.resize(n);
            P.resize(n);
            psi.resize(n);
        }
    };
    // Kinematics of particle a, filling scratch.xr and scratch.w for its neighbours; at the
    // reference configuration (atReference) f = I, H = 0 and G = K without computing them.
    Kinematics kinematics(std::size_t a, const std::vector<Vec<D>>& x,
                          const ReferenceConfiguration<D>& ref, bool atReference,
                          Scratch& scratch) const;

    // The count stress samples of particle a into scratch.F: F_b(a) = F_a + G_a x^r_ba (filled:
    // already there, fillFramedSamples'), or, with particleVolume, F̄_b(a) (scratch.alpha the
    // factors). With measure, returns the smallest det F_b(a) (positive unless a sample is
    // inverted, §G13), else +inf (GradFSampleVolume.cpp).
    double fillSamples(const Kinematics& kin, std::size_t count, Scratch& scratch,
                       bool particleVolume, bool measure = false, bool filled = false) const;
    // Total-Lagrangian elasticState (§G26): particle a's samples F_a + H°_a[y°_ab] F°_a (G26.1)
    // at positions x into scratch.F, y°_ab into scratch.xr (the offsets the force's Q takes)
    // and the fit of H°_a (G26.2) into scratch.frame (GradFSampleFrames.cpp). Reads scratch.w.
    void fillFramedSamples(std::size_t a, const std::vector<Vec<D>>& x, const NeighbourList& list,
                           const Kinematics& kin, Scratch& scratch) const;
    // Whether particle a's samples are framed (§G25): a material with history under
    // total-Lagrangian elasticState.
    bool framed(const Material<D>& material) const
    {
        return frames_.active() && material.hasHistory();
    }

private:
    // sampleVolume particle: the samples' stresses P̄ at F̄_b(a) in scratch.P become the
    // derivatives of Ψ(F̄_b(a)) with respect to F_b(a), α_b dev(τ̄_b) F̄_b^{-T}; returns the
    // samples' weighted mean pressure Σ_b Ŵ_ab tr(τ̄_b) / D, which acts through F_a (§G13).
    double chainParticleVolume(std::size_t count, Scratch& scratch) const;

    // fit joint (GradFJointFit.cpp): A_a⁻¹ of (G17.2) from the blocks of the sequential fit's
    // sums, the Schur complement's inverse regularised as Z_a's; returns the complement C_a
    // that completes f_a on a singular support (zero on any other).
    Mat<D> invertJointMatrix(const Mat<D>& Mxx, const MatMD& Y, const MatM& Z, MatP& Ainv) const;
    // fit joint: f_a and H_a of (G17.2) into kin, scratch.xr and scratch.w for b ≠ a.
    void jointKinematics(std::size_t a, const std::vector<Vec<D>>& x,
                         const ReferenceConfiguration<D>& ref, Scratch& scratch,
                         Kinematics& kin) const;
    // fit joint: particle a's terms of the force (G17.3) into UL_, Cw_ and selfTerm_, from
    // A_a and B_a of spec §6.4 (the derivatives of Π_a with respect to f_a and H_a).
    void jointForceTerms(std::size_t a, double V0, const Mat<D>& A, const Tensor3<D>& B);

    // The least-squares matrix's smallest eigenvalue, relative to its mean (regularisedInverse).
    static constexpr double smallestEigenvalue = 0.02;


    std::vector<double> invDenominator_; // 1 / Σ_e W_ae V^r_e
    std::vector<MatM> Zinv_;             // Z_a^{-1} (the sequential fit only)
    std::vector<MonomialVec<D>> s_;      // s_a = Σ_e Ŵ_ae z_ae
    std::vector<MatMD> Y_;               // Y_a = Σ_e Ŵ_ae z_ae ⊗ x^r_ea (sequential only)
    // fit joint (§G17): A_a⁻¹ of (G17.2) and the linear part of r_a, Σ_e Ŵ_ae x^r_ea.
    std::vector<MatP> Ainv_;
    std::vector<Vec<D>> firstMoment_;
    std::vector<Mat<D>> jointComplement_; // C_a: f_a's part no neighbour sees (deficient supports)
    std::size_t maxNeighbours_ = 0;

    // Per-particle results of the first pass, gathered by the second.
    // fit joint: N_a = V0_a [A_a | B~_a] A_a^{-1} in their place (G17.3): UL_ its first D
    // columns and Cw_ the rest, both / Σ_e W_ae V^r_e, selfTerm_ N_a r_a.
    std::vector<Mat<D>> UL_;          // V0_a (A_a - C_a Y_a) L_a
    std::vector<MatDM> Cw_;           // V0_a C_a / Σ_e W_ae V^r_e
    std::vector<Vec<D>> selfTerm_;    // V0_a C_a s_a
    ChunkCache chunkCache_;

    // Materials with history: the samples' states and V0_a Σ_b Ŵ_ab D_b of each particle's
    // samples at the last evaluation (what its commit dissipates).
    bool linearised_ = false;   // plasticSamples linearised
    bool elasticState_ = false; // plasticSamples elasticState
    bool referenceMoves_ = true; // Args::referenceMoves (false: total Lagrangian)
    // Total-Lagrangian elasticState (§G25): the samples' frames, and the list of the last force
    // evaluation (the commit moves the frames along it).
    SampleFrames<D> frames_;
    const NeighbourList* framedList_ = nullptr;
    // V0_a C°_a / Σ_e W_ae V^r_e of (G26.3), gathered over the frame's offsets (zero for a
    // particle whose samples are not framed).
    std::vector<MatDM> frameCw_;
    std::vector<Mat<D>> frameUL_; // fit joint (G26.5): the linear part of V0_a N°_a / Σ_e W_ae V^r_e
    // (G26.3): the samples' derivative with respect to H°_a (B arrives as Q_a, total Lagrangian)
    // moved onto F_a (into A) and the pairs (frameCw_, selfTerm); B is left zero: the fit in X
    // carries no H (GradFSampleFrames.cpp).
    void frameForceTerms(std::size_t a, double V0, const typename Scratch::FrameFit& fit,
                         Mat<D>& A, Tensor3<D>& B, Vec<D>& selfTerm);
    Vec<D> frameOffset(std::size_t a, std::size_t c) const
    {
        return frames_.position(a) - frames_.position(c);
    }
    void moveSampleFrames(const HistoryCommit<D>& in); // GradFSampleFrames.cpp
    // moveWeights (§G9): the samples' energy weights are chosen at each move (per-pair state in
    // samples_), and the evaluation after a move (weightsDue_) chooses them.
    enum class MoveWeights
    {
        kernel,
        conserving,
        nonIncreasing
    };
    MoveWeights weights_ = MoveWeights::kernel;
    // openedSamples particle (§G22): at a move the samples of an opened particle take its
    // state; V0_a Σ_b ω_ab (W_old − W_new) of each particle a's samples at the last move.
    bool openedFromParticle_ = false;
    std::vector<double> openingDissipation_;
    void takeOpenedStates(const std::vector<Vec<D>>& x, const ReferenceConfiguration<D>& ref,
                          const std::vector<int>& body,
                          const std::vector<Material<D>*>& materials);
    bool weightsDue_ = false;
    bool particleVolume_ = false; // sampleVolume particle (§G13)
    bool jointFit_ = false;       // fit joint (§G17)
    // samplePoints moments (docs/theory/gradF-moments.md), and where the key was written, for
    // the refusal of a material with history under updated Lagrangian (§M4).
    MomentSamples<D> moments_;
    SourceLocation samplePointsWhere_;
    // §M4: a material with history under updated Lagrangian needs plasticSamples elasticState
    // (§M7) with moment points.
    void refuseMovingMomentHistory(const std::vector<const Material<D>*>& materials) const;
    // What a force evaluation's first half of a particle hands its second (computeForces).
    struct ParticleStart
    {
        Mat<D> F;              // F_a
        std::size_t count = 0; // its samples
        bool bar = false;      // sampleVolume particle on its body
        bool framed = false;
        bool weighted = false; // moveWeights' energy weights
        bool wantPsi = false;  // the samples' energies
    };
    // Up to this many particles' moment points side by side in one block of lanes (3 in 2D, 2
    // in 3D), which a plastic material returns together: five or seven points alone filled a
    // block of eight or sixteen lanes and a row of states each.
    static constexpr std::size_t maxSampleGroup =
        std::max<std::size_t>(1, HistoryOf::rowBlock / MomentPoints<D>::count);
    bool groupSamples_ = true;
    // Whether a body of this material evaluates its particles' moment points in groups: a
    // material with plastic history in rows, its samples neither linearised, framed nor
    // weighted.
    bool groupsSamples(const Material<D>& material) const
    {
        return moments_.active() && groupSamples_ && maxSampleGroup > 1 && material.hasHistory() &&
               !linearised_ && !frames_.active() && !samples_.weighted() &&
               material.readsStatesInRows();
    }
    // How many particles from a (below end, one chunk's body, whose material groupsSamples())
    // are evaluated together: those with moment points, at most maxSampleGroup (at least 1).
    std::size_t sampleGroup(std::size_t a, std::size_t end) const
    {
        return moments_.run(a, end, maxSampleGroup);
    }
    struct SampleGroupScratch
    {
        Scratch members[maxSampleGroup - 1]; // the group's members after the first
        ParticleStart starts[maxSampleGroup - 1];
        Mat<D> F[HistoryOf::rowBlock];
        Mat<D> P[HistoryOf::rowBlock];
        double psi[HistoryOf::rowBlock];
        double dissipation[HistoryOf::rowBlock];
        std::uint8_t changed[HistoryOf::rowBlock];
        std::vector<double> states; // in rows
        std::vector<double> next;   // packed
    };
    // evaluateSamples() of the particles a .. a + group - 1 (sampleGroup's) in one call of the
    // material: their samples side by side, each particle's slice back into its scratch and its
    // pending states kept in particle order, as evaluating them one by one does, bit for bit.
    void evaluateSampleGroup(std::size_t a, std::size_t group, const Material<D>& material,
                             bool psi, Scratch* const* members, SampleGroupScratch& g);
    // elasticState: the particles with history, whose K the move sets to zero and whose F^r
    // it sets to the dilation J^(1/D) I (§G4), marked by moveHistory() for the
    // referenceUpdate() that follows it.
    std::vector<std::uint8_t> spatialFrame_;
    // J_a^(1/D) of those particles at the positions moveHistory() was given, handed to the
    // referenceUpdate() that follows it with the same positions (which would compute the same
    // kinematics again), and taken by it: `mutable` for that hand-over only.
    mutable std::vector<double> movedFrames_;
    mutable const Vec<D>* movedFramesAt_ = nullptr;
    // elasticState: an inverted stress sample found by moveHistory() (det f_b(a) <= 0: its
    // rebased state would be the mirror image's, which the materials cannot tell apart, §G3),
    // reported by the referenceUpdate() that follows it.
    ForceStatus sampleInversion_;
    SampleHistory<D> samples_;
    std::vector<double> sampleDissipation_;
    std::vector<double> dissipationAside_; // setAsideEvaluation()
    // Where the samples around particle a find their history: their states read into
    // scratch (and, with pending, where the evaluation puts the states to commit).
    HistoryOf historyAround(std::size_t a, const Material<D>& material, std::size_t count,
                            Scratch& scratch, bool pending);
    // P(F_b(a)) (and Ψ when psi is not null) of particle a's count samples in scratch.F; with
    // pending, also the states a commit would make of them (a force evaluation).
    void evaluateSamples(std::size_t a, const Material<D>& material, std::size_t count,
                         double* psi, Scratch& scratch, bool pending);
    // moveWeights (§G9): puts particle a's energy weights into scratch.w in place of the
    // kernel's: those of its samples, or, in the first evaluation after a move (weightsDue_),
    // chosen from scratch.psi, the samples' energies at the reference (F_b(a) = Fr for all b),
    // and kept for the samples when `keep`; the kernel's on a first layout. Returns the energy
    // the choice could not keep (0 to round-off).
    double useEnergyWeights(std::size_t a, const Material<D>& material, std::size_t count,
                            const Mat<D>& Fr, bool keep, Scratch& scratch);
};

} // namespace sph
