// gradF's force (spec §6.4) and energy (spec §6.3), a particle at a time around the evaluation of
// its stress samples (GradFHistory.cpp for a material with history). What depends only on the
// reference is GradFPrepare.cpp, the kinematics GradFKinematics.cpp.
#include "particles/Parallel.hpp"
#include "stabilisation/gradF/GradF.hpp"
#include "stabilisation/gradF/MonomialTensors.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>

namespace sph
{

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
        frameCw_.resize(n);
        frameUL_.resize(jointFit_ ? n : 0);
    }
    sampleDissipation_.resize(n);
    std::vector<ChunkTally> tallies(chunks.size());
#pragma omp parallel if (useThreads(n))
    {
        Scratch scratch;
        scratch.resize(maxNeighbours_);
        ParticleStart started;
        // The other members of a group (sampleGroup) on the heap, and only with moment points:
        // the thread's stack frame stays what it was without them.
        std::unique_ptr<SampleGroupScratch> group;
        Scratch* members[maxSampleGroup] = {&scratch};
        ParticleStart* starts[maxSampleGroup] = {&started};
        if (moments_.active())
        {
            group = std::make_unique<SampleGroupScratch>();
            for (std::size_t k = 1; k < maxSampleGroup; ++k)
            {
                group->members[k - 1].resize(maxNeighbours_);
                members[k] = &group->members[k - 1];
                starts[k] = &group->starts[k - 1];
            }
        }
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
            // Each particle in two halves around the evaluation of its samples; particles whose
            // moment points share one block of lanes (sampleGroup) are evaluated together, each
            // otherwise as alone (theory gradF-moments.md §M5).
            const auto start = [&](std::size_t a, Scratch& scratch, ParticleStart& st)
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
                st.F = kin.F;
                // Stresses at F_b(a) = F_a + G_a x^r_ba (or F̄_b(a)) for every neighbour b
                // (incl. a), or at the moment points F_a + G_a ξ_q.
                const std::size_t count =
                    moments_.use(a, list.count(a), scratch.xr.data(), scratch.w.data(),
                                 moments_.carriesStates() && material.hasHistory());
                st.count = count;
                const bool bar = particleVolume_ && material.hasHistory();
                st.bar = bar;
                const bool framed = this->framed(material);
                st.framed = framed;
                if (framed)
                {
                    fillFramedSamples(a, in.x, list, kin, scratch);
                }
                if (frames_.active())
                {
                    // Every particle's (a body without history too: its frame is written out).
                    frames_.evaluated(a, kin.F, framed ? scratch.frame.H : Tensor3<D>::zero());
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
                st.weighted = weighted;
                st.wantPsi = wantEnergy || choose;
            };
            const auto finish = [&](std::size_t a, Scratch& scratch, const ParticleStart& st)
            {
                const std::size_t count = st.count;
                const bool bar = st.bar;
                const bool framed = st.framed;
                const bool weighted = st.weighted;
                if (weighted)
                {
                    useEnergyWeights(a, material, count, st.F, true, scratch);
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
                    S.noalias() += wP;
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
                    S.noalias() += pressure * st.F.inverse().transpose();
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
                Vec<D> frameSelfTerm = Vec<D>::Zero();
                if (framed)
                {
                    frameForceTerms(a, in.V0[a], scratch.frame, A, B, frameSelfTerm); // (G26.3)
                }
                else if (frames_.active())
                {
                    frameCw_[a].setZero();
                    if (jointFit_)
                    {
                        frameUL_[a].setZero();
                    }
                }
                if (jointFit_)
                {
                    jointForceTerms(a, in.V0[a], A, B); // (G17.3)
                    selfTerm_[a] += frameSelfTerm;
                    return;
                }
                const MatDM C = contractMonomials<D, MatDM>(B) * Zinv_[a];
                const Mat<D> Atilde = A - C * Y_[a];
                UL_[a] = in.V0[a] * Atilde * ref.gradient.L[a];
                Cw_[a] = (in.V0[a] * invDenominator_[a]) * C;
                selfTerm_[a] = in.V0[a] * (C * s_[a]) + frameSelfTerm;
            };
            const bool grouping = groupsSamples(material);
            for (std::size_t a = chunk.begin; a < chunk.end;)
            {
                const std::size_t size = grouping ? sampleGroup(a, chunk.end) : 1;
                for (std::size_t k = 0; k < size; ++k)
                {
                    start(a + k, *members[k], *starts[k]);
                }
                if (size == 1)
                {
                    evaluateSamples(a, material, started.count,
                                    started.wantPsi ? scratch.psi.data() : nullptr, scratch, true);
                }
                else
                {
                    evaluateSampleGroup(a, size, material, started.wantPsi, members, *group);
                }
                for (std::size_t k = 0; k < size; ++k)
                {
                    finish(a + k, *members[k], *starts[k]);
                }
                a += size;
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
                    if (frames_.active())
                    {
                        const Vec<D> y = frameOffset(a, c); // (G26.5)
                        sum.noalias() +=
                            values.W[j] * (frameCw_[a] * monomials<D>(y) - frameUL_[a] * y);
                    }
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
                if (frames_.active())
                {
                    sum.noalias() +=
                        values.W[j] * (frameCw_[a] * monomials<D>(frameOffset(a, c)));
                }
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
            const std::size_t count =
                moments_.use(a, list.count(a), scratch.xr.data(), scratch.w.data(),
                             moments_.carriesStates() && material.hasHistory());
            const bool framed = this->framed(material);
            if (framed)
            {
                fillFramedSamples(a, in.x, list, kin, scratch);
            }
            fillSamples(kin, count, scratch, particleVolume_ && material.hasHistory(), false, framed);
            evaluateSamples(a, material, count, scratch.psi.data(), scratch, false);
            if (samples_.weighted() && material.hasHistory())
            {
                // Between a move and the evaluation after it: the weights it will choose.
                useEnergyWeights(a, material, count, kin.F, false, scratch);
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
