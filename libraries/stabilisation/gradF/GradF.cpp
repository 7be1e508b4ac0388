#include "particles/Parallel.hpp"
#include "stabilisation/gradF/GradF.hpp"
#include "stabilisation/gradF/MonomialTensors.hpp"
#include "stabilisation/gradF/RegularisedInverse.hpp"

#include <cmath>
#include <stdexcept>

namespace sph
{

template <int D>
std::string GradF<D>::description()
{
    return "The seed paper's gradient-of-F stabilisation (Saito & Kusachi 2017): energy "
           "sum_a V0_a sum_b W^_ab Psi(F_a + G_a x_ba), exact force of spec §6.4. No tuning "
           "parameter.";
}

template <int D>
Schema GradF<D>::schema()
{
    return Schema().add(Key::word("plasticSamples",
                                  "materials with history: ownHistory (every stress sample keeps "
                                  "its own; exact energy), elasticState (plastic flow: samples "
                                  "carry their elastic state and extrapolate only the motion "
                                  "since the last reference move (updated Lagrangian) or the "
                                  "last step (total Lagrangian, §G25) instead of the total "
                                  "gradient of F; docs/theory/gradF-plastic.md) or linearised "
                                  "(the return's "
                                  "correction at F_a, linearised; for comparison)")
                            .choices({"ownHistory", "elasticState", "linearised"})
                            .defaultValue("ownHistory"))
        .add(Key::word("moveWeights",
                       "plasticSamples elasticState: the samples' energy weights at a reference "
                       "move: kernel (the new reference's kernel weights, as the paper; "
                       "consistent, a move may change the energy), conserving (chosen so that no "
                       "move changes the energy; the quadrature then lags the configuration) or "
                       "nonIncreasing (so that no move raises it); "
                       "docs/theory/gradF-plastic.md §G9")
                 .choices({"kernel", "conserving", "nonIncreasing"})
                 .defaultValue("kernel"))
        .add(Key::word("openedSamples",
                       "plasticSamples elasticState: the samples of an opened particle (sand "
                       "beyond its tension cut-off): own (their own states) or particle (at each "
                       "move they take its state, the energy they held booked as dissipated; "
                       "docs/theory/gradF-plastic.md §G22)")
                 .choices({"own", "particle"})
                 .defaultValue("own"))
        .add(Key::word("sampleVolume",
                       "the volume change of the stress samples: own (each sample's det F_b(a), "
                       "as the paper) or particle (every sample of a particle takes the "
                       "particle's det F_a, the F-bar method: the samples' spread stays isochoric, "
                       "so isochoric plastic flow does not lock; it acts on bodies whose material "
                       "has a plastic history, 2D and 3D; with `impenetrability` in sphSchemes, "
                       "docs/theory/gradF-plastic.md §G13-§G14)")
                 .choices({"own", "particle"})
                 .defaultValue("own"))
        .add(Key::word("fit",
                       "how F_a and its gradient are fitted to the neighbours: sequential (as the "
                       "paper: F_a the corrected gradient, then its gradient by least squares with "
                       "F_a fixed) or joint (both from one least-squares fit of the second-order "
                       "Taylor expansion: the stress samples exact for quadratic motions at free "
                       "surfaces and on disordered neighbourhoods too, where the sequential fit's "
                       "carry a first-order error; docs/theory/gradF-plastic.md §G17)")
                 .choices({"sequential", "joint"})
                 .defaultValue("sequential"));
}

template <int D>
GradF<D>::GradF(const Params& params, const typename Stabilisation<D>::Args& args)
    : linearised_(params.word("plasticSamples") == "linearised"),
      elasticState_(params.word("plasticSamples") == "elasticState"),
      referenceMoves_(args.referenceMoves),
      weights_(!elasticState_ || params.word("moveWeights") == "kernel" ? MoveWeights::kernel
               : params.word("moveWeights") == "conserving"                ? MoveWeights::conserving
                                                                           : MoveWeights::nonIncreasing),
      openedFromParticle_(params.word("openedSamples") == "particle"),
      particleVolume_(params.word("sampleVolume") == "particle"),
      jointFit_(params.word("fit") == "joint")
{
    // Only samples that carry their elastic state have weights to choose.
    if (!elasticState_ && params.given("moveWeights") && params.word("moveWeights") != "kernel")
    {
        params.fail("moveWeights",
                    "moveWeights " + params.word("moveWeights") +
                        " chooses the energy weights of samples that carry their elastic state, "
                        "but plasticSamples is " + params.word("plasticSamples"),
                    {"hint: add 'plasticSamples elasticState;' or remove moveWeights"});
    }
    if (!elasticState_ && openedFromParticle_)
    {
        params.fail("openedSamples",
                    "openedSamples particle gives the samples of an opened particle its state "
                    "at each reference move, which only samples that carry their elastic state "
                    "across the moves have, but plasticSamples is " +
                        params.word("plasticSamples"),
                    {"hint: add 'plasticSamples elasticState;' (with formulation "
                     "updatedLagrangian) or remove openedSamples"});
    }
    // Both act at reference moves, which a total-Lagrangian run never makes (its elasticState
    // frames move at the commits, §G25, with the reference's fixed weights).
    if (!referenceMoves_ && params.given("moveWeights") && params.word("moveWeights") != "kernel")
    {
        params.fail("moveWeights",
                    "moveWeights " + params.word("moveWeights") +
                        " chooses the samples' energy weights at each reference move, and "
                        "formulation totalLagrangian never moves its reference",
                    {"hint: remove moveWeights (kernel, the default), or use formulation "
                     "updatedLagrangian"});
    }
    if (!referenceMoves_ && openedFromParticle_)
    {
        params.fail("openedSamples",
                    "openedSamples particle acts at each reference move, and formulation "
                    "totalLagrangian never moves its reference",
                    {"hint: remove openedSamples (own, the default), or use formulation "
                     "updatedLagrangian"});
    }
    // In 1D F̄_b(a) = (J_a / F_b) F_b = F_a for every sample: nothing of gradF would be left.
    if (D == 1 && particleVolume_)
    {
        params.fail("sampleVolume",
                    "sampleVolume particle in 1D gives every stress sample the particle's F "
                    "(a volume ratio is all a 1D F has), which removes gradF's stabilisation",
                    {"hint: remove sampleVolume (own, the default) in a 1D case"});
    }
}

template <int D>
ForceStatus GradF<D>::prepare(const ReferenceConfiguration<D>& ref)
{
    const NeighbourList& list = ref.neighbours;
    const std::size_t n = ref.size();
    invDenominator_.resize(n);
    s_.resize(n);
    // Z⁻¹ and Y are the sequential fit's; the joint fit keeps A⁻¹ instead (432 B per particle
    // in 3D not held).
    Zinv_.resize(jointFit_ ? 0 : n);
    Y_.resize(jointFit_ ? 0 : n);
    maxNeighbours_ = list.maxCount();
    samples_.listChanged();
    if (jointFit_)
    {
        Ainv_.resize(n);
        firstMoment_.resize(n);
        jointComplement_.resize(n);
    }
    long singular = -1;
#pragma omp parallel for schedule(static) reduction(max : singular) if (useThreads(n))
    for (std::size_t a = 0; a < n; ++a)
    {
        const std::size_t first = list.begin(a);
        const double* W = ref.kernelValues(a).W; // W[k - first] for slot k
        double denominator = 0.0;
        for (std::size_t k = first; k < list.end(a); ++k)
        {
            denominator += W[k - first] * ref.V[list.indices[k]];
        }
        invDenominator_[a] = 1.0 / denominator;
        MatM Z = MatM::Zero();
        MonomialVec<D> s = MonomialVec<D>::Zero();
        MatMD Y = MatMD::Zero();
        Mat<D> Mxx = Mat<D>::Zero(); // fit joint: Σ Ŵ x^r ⊗ x^r
        Vec<D> moment = Vec<D>::Zero();
        for (std::size_t k = list.begin(a) + 1; k < list.end(a); ++k)
        {
            const Vec<D> xr = ref.x[list.indices[k]] - ref.x[a];
            const MonomialVec<D> z = monomials<D>(xr);
            const double w = W[k - first] * ref.V[list.indices[k]] * invDenominator_[a]; // Ŵ_ak
            Z.noalias() += w * z * z.transpose();
            s += w * z;
            Y.noalias() += w * z * xr.transpose();
            if (jointFit_)
            {
                Mxx.noalias() += (w * xr) * xr.transpose();
                moment += w * xr;
            }
        }
        if (jointFit_)
        {
            firstMoment_[a] = moment;
            jointComplement_[a] = invertJointMatrix(Mxx, Y, Z, Ainv_[a]);
        }
        // Z is SPD with at least M non-degenerate neighbours; judge it scale-free.
        const double scale = Z.trace() / M;
        const double det = (Z / scale).determinant();
        if ((!(scale > 0.0) || !(det > 1.0e-12) || !std::isfinite(det)) && ref.counts(a))
        {
            singular = std::max<long>(singular, static_cast<long>(n - a));
        }
        s_[a] = s;
        if (!jointFit_)
        {
            Zinv_[a] = regularisedInverse(Z, scale, smallestEigenvalue);
            Y_[a] = Y;
        }
    }
    if (singular < 0)
    {
        return {};
    }
    return ForceStatus::failed(FailureKind::singularReference, static_cast<long>(n) - singular,
                               0.0, "least-squares matrix Z (too few neighbours in x^r)");
}

template <int D>
ForceStatus GradF<D>::computeForces(const ForceInput<D>& in, ForceOutput<D>& out, bool wantEnergy)
{
    const ReferenceConfiguration<D>& ref = in.ref;
    const NeighbourList& list = ref.neighbours;
    const std::size_t n = ref.size();
    out.T.resize(n);
    out.F.resize(n);
    out.P.resize(n);
    UL_.resize(n);
    Cw_.resize(n);
    selfTerm_.resize(n);
    const std::vector<ParticleChunk>& chunks = chunkCache_.of(in.bodies);
    const bool carriesK = !ref.K.empty();
    samples_.follow(list, in.body, in.materials, in.globalId, elasticState_ ? &ref.F : nullptr);
    samples_.clearPending(); // this evaluation's states are the ones to commit
    if (frames_.active())
    {
        frames_.start(ref.x); // total Lagrangian: x^r = X
        frames_.evaluatedAt(in.x);
        framedList_ = &list;
    }
    sampleDissipation_.resize(n);
    std::vector<ChunkTally> tallies(chunks.size());
#pragma omp parallel if (useThreads(n))
    {
        Scratch scratch;
        scratch.resize(maxNeighbours_);
        // Chunks handed out as threads come free: a flowing region costs several times a
        // resting one (returns, rebases), and a static split left a thread idle ~10 % of the
        // step on the column collapse. Every result is per chunk or per particle (the tallies
        // are combined in chunk order), so the split does not change a digit.
#pragma omp for schedule(dynamic, 1)
        for (std::size_t i = 0; i < chunks.size(); ++i)
        {
            const ParticleChunk& chunk = chunks[i];
            const Material<D>& material = *in.materials[chunk.body];
            ChunkTally& tally = tallies[i];
            for (std::size_t a = chunk.begin; a < chunk.end; ++a)
            {
                Kinematics kin = kinematics(a, in.x, ref, in.atReference, scratch);
                double J;
                if (!admissible<D>(kin.F, J))
                {
                    if (in.counts(a))
                    {
                        tally.flagJacobian(a, J);
                    }
                    kin.F.setIdentity(); // keep the arithmetic finite; the run stops
                    kin.G = Tensor3<D>::zero();
                }
                out.F[a] = kin.F;
                // Stresses at F_b(a) = F_a + G_a x^r_ba (or F̄_b(a)) for every neighbour b
                // (incl. a).
                const std::size_t count = list.count(a);
                const bool bar = particleVolume_ && material.hasHistory();
                const bool framed = this->framed(material);
                if (frames_.active())
                {
                    // Every particle's (a body without history too: its frame is written out).
                    frames_.evaluated(a, kin.F, kin.G);
                }
                if (framed)
                {
                    fillFramedSamples(a, list, kin, scratch);
                }
                // (Framed samples are always measured: §G25's admissibility.)
                const double smallestSample =
                    fillSamples(kin, count, scratch, bar, bar || framed, framed);
                if ((bar || framed) && !(smallestSample > 0.0) && in.counts(a))
                {
                    tally.flagJacobian(a, smallestSample);
                }
                const bool weighted = samples_.weighted() && material.hasHistory();
                const bool choose = weighted && weightsDue_;
                evaluateSamples(a, material, list, count,
                                wantEnergy || choose ? scratch.psi.data() : nullptr, scratch, true);
                if (weighted)
                {
                    useEnergyWeights(a, material, list, kin.F, true, scratch);
                }
                if (material.hasHistory() && !linearised_)
                {
                    double dissipation = 0.0;
                    for (std::size_t j = 0; j < count; ++j)
                    {
                        dissipation += scratch.w[j] * scratch.dissipation[j];
                    }
                    sampleDissipation_[a] = in.V0[a] * dissipation;
                }
                out.P[a] = scratch.P[0]; // b = a: F_a(a) = F_a
                const double pressure = bar ? chainParticleVolume(count, scratch) : 0.0;
                // S_a = Σ Ŵ P_b,  Q_a[k] = Σ Ŵ x^r_ba,k P_b
                Mat<D> S = Mat<D>::Zero();
                Tensor3<D> Q = Tensor3<D>::zero();
                double energy = 0.0;
                for (std::size_t j = 0; j < count; ++j)
                {
                    const double w = scratch.w[j];
                    const Mat<D> wP = w * scratch.P[j];
                    if (framed)
                    {
                        S.noalias() += wP * scratch.M[j].transpose(); // (G25.2)
                    }
                    else
                    {
                        S.noalias() += wP;
                    }
                    for (int d = 0; d < D; ++d)
                    {
                        Q.slice[static_cast<std::size_t>(d)].noalias() += scratch.xr[j][d] * wP;
                    }
                    if (wantEnergy)
                    {
                        energy += w * scratch.psi[j];
                    }
                }
                if (in.counts(a))
                {
                    tally.energy += in.V0[a] * energy;
                }
                if (bar)
                {
                    S.noalias() += pressure * kin.F.inverse().transpose();
                }
                // A = S F^r^T + Q:K,  B[k] = Q[k] F^r^T,  C = B~ Z^{-1},  Ã = A - C Y
                const Mat<D> FrT = ref.F[a].transpose();
                Mat<D> A = S * FrT;
                Tensor3<D> B;
                for (int d = 0; d < D; ++d)
                {
                    const auto dd = static_cast<std::size_t>(d);
                    B.slice[dd] = Q.slice[dd] * FrT;
                    if (carriesK)
                    {
                        A.noalias() += Q.slice[dd] * ref.K[a].slice[dd].transpose();
                    }
                }
                if (jointFit_)
                {
                    jointForceTerms(a, in.V0[a], A, B); // (G17.3)
                    continue;
                }
                const MatDM C = contractMonomials<D, MatDM>(B) * Zinv_[a];
                const Mat<D> Atilde = A - C * Y_[a];
                UL_[a] = in.V0[a] * Atilde * ref.gradient.L[a];
                Cw_[a] = (in.V0[a] * invDenominator_[a]) * C;
                selfTerm_[a] = in.V0[a] * (C * s_[a]);
            }
        }
        // T_c = -V^r_c Σ_{a≠c} [UL_a d_ac + W_ca Cw_a z_ac] - UL_c e_c + V0_c C_c s_c
#pragma omp for schedule(static)
        for (std::size_t c = 0; c < n; ++c)
        {
            Vec<D> sum = Vec<D>::Zero();
            const typename ReferenceConfiguration<D>::PairKernelValues values = ref.kernelValues(c);
            if (jointFit_)
            {
                // (G17.3): p_ac = (x^r_ca, z(x^r_ca)) with x^r_ca = -xr.
                for (std::size_t k = list.begin(c) + 1, j = 1; k < list.end(c); ++k, ++j)
                {
                    const std::size_t a = list.indices[k];
                    const Vec<D> xr = ref.x[a] - ref.x[c];
                    sum.noalias() += values.W[j] * (Cw_[a] * monomials<D>(xr) - UL_[a] * xr);
                }
                out.T[c] = -ref.V[c] * sum + selfTerm_[c];
                continue;
            }
            for (std::size_t k = list.begin(c) + 1, j = 1; k < list.end(c); ++k, ++j)
            {
                const std::size_t a = list.indices[k];
                const Vec<D> xr = ref.x[a] - ref.x[c];
                sum.noalias() += UL_[a] * (values.dWdrOverR[j] * xr); // d_ac = ∇W_ac = -∇W_ca
                sum.noalias() += values.W[j] * (Cw_[a] * monomials<D>(xr));
            }
            out.T[c] = -ref.V[c] * sum - UL_[c] * ref.gradient.e[c] + selfTerm_[c];
        }
    }
    if (weightsDue_)
    {
        weightsDue_ = false;
        samples_.clearLeaving();
    }
    ForceStatus status = combine(tallies);
    checkForces<D>(out.T, status, in.owned);
    return status;
}

template <int D>
double GradF<D>::energy(const ForceInput<D>& in)
{
    const ReferenceConfiguration<D>& ref = in.ref;
    const NeighbourList& list = ref.neighbours;
    samples_.follow(list, in.body, in.materials, in.globalId, elasticState_ ? &ref.F : nullptr);
    if (frames_.active())
    {
        frames_.start(ref.x);
    }
    // Each particle's share in parallel, summed in particle order (thread-count independent).
    const std::size_t n = ref.size();
    std::vector<double> share(n, 0.0);
#pragma omp parallel if (useThreads(n))
    {
        Scratch scratch; // kinematics() fills x^r_ba and Ŵ_ab
        scratch.resize(maxNeighbours_);
#pragma omp for schedule(static)
        for (std::size_t a = 0; a < n; ++a)
        {
            if (!in.counts(a))
            {
                continue;
            }
            const Material<D>& material = *in.materials[static_cast<std::size_t>(in.body[a])];
            const Kinematics kin = kinematics(a, in.x, ref, false, scratch);
            double sum = 0.0;
            const std::size_t count = list.count(a);
            const bool framed = this->framed(material);
            if (framed)
            {
                fillFramedSamples(a, list, kin, scratch);
            }
            fillSamples(kin, count, scratch, particleVolume_ && material.hasHistory(), false, framed);
            evaluateSamples(a, material, list, count, scratch.psi.data(), scratch, false);
            if (samples_.weighted() && material.hasHistory())
            {
                // Between a move and the evaluation after it: the weights it will choose.
                useEnergyWeights(a, material, list, kin.F, false, scratch);
            }
            for (std::size_t j = 0; j < count; ++j)
            {
                sum += scratch.w[j] * scratch.psi[j];
            }
            share[a] = in.V0[a] * sum;
        }
    }
    double total = 0.0;
    for (const double e : share)
    {
        total += e;
    }
    return total;
}

template class GradF<1>;
template class GradF<2>;
template class GradF<3>;

SPH_REGISTER_DIM_MODEL(Stabilisation, GradF, "gradF");

} // namespace sph
