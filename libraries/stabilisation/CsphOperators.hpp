#pragma once
// Building blocks shared by the CSPH schemes (spec §2-§4):
//
//   f_a = Σ_b x_b ⊗ g_a(b) = [Σ_{b≠a} V_b x_ba ⊗ d_ab] L_a^T (+ C_a)    (eq. 9, spec §2)
//   T_c = -Σ_a U_a g_a(c),  U_a = V0_a P_a F^r_a^T                       (spec §4)
//       = -V_c Σ_{a≠c} (U_a L_a) d_ac - (U_c L_c) e_c                     (gather form)
//
// where d_ab is the gradient used for the pair. `GradientSet` supplies it, for one particle a
// at a time (what a needs of its pairs fetched once):
//   particle(a).outgoing(k)  d_ab for slot k of a's list (pair a -> b)
//   particle(a).incoming(k)  d_ba for slot k of a's list (the gradient b's operator uses for a)
//   L(a), e(a)   the corrected-gradient data; gradient() all of it (f_a with C_a).
// For the standard kernel gradient incoming(k) = -outgoing(k) (the kernel gradient is odd);
// the `vidal` scheme supplies shifted gradients instead.

#include "particles/Parallel.hpp"
#include "stabilisation/Stabilisation.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace sph
{

// The standard corrected kernel gradient of the reference configuration.
template <int D>
struct StandardGradients
{
    const ReferenceConfiguration<D>& ref;

    struct Particle
    {
        const ReferenceConfiguration<D>& ref;
        std::size_t a;
        const double* dWdrOverR; // a's kernel values (stored or recomputed)
        Vec<D> outgoing(std::size_t k) const { return ref.gradW(a, k, dWdrOverR); }
        Vec<D> incoming(std::size_t k) const { return -ref.gradW(a, k, dWdrOverR); }
    };
    Particle particle(std::size_t a) const { return {ref, a, ref.kernelValues(a).dWdrOverR}; }
    const Mat<D>& L(std::size_t a) const { return ref.gradient.L[a]; }
    const Vec<D>& e(std::size_t a) const { return ref.gradient.e[a]; }
    const CorrectedGradient<D>& gradient() const { return ref.gradient; }
};

// Pair gradients stored per pair slot k = (a, b) with their corrected gradient: the `vidal`
// scheme's shifted kernel gradients, the `oneSided` scheme's one-sided ones.
template <int D>
struct StoredGradients
{
    const std::vector<Vec<D>>& out; // d_ab, the gradient a's operator uses for b
    const std::vector<Vec<D>>& in;  // d_ba, the gradient b's operator uses for a
    const CorrectedGradient<D>& corrected;

    struct Particle
    {
        const std::vector<Vec<D>>& out;
        const std::vector<Vec<D>>& in;
        const Vec<D>& outgoing(std::size_t k) const { return out[k]; }
        const Vec<D>& incoming(std::size_t k) const { return in[k]; }
    };
    Particle particle(std::size_t) const { return {out, in}; }
    const Mat<D>& L(std::size_t a) const { return corrected.L[a]; }
    const Vec<D>& e(std::size_t a) const { return corrected.e[a]; }
    const CorrectedGradient<D>& gradient() const { return corrected; }
};

// f_a at positions x.
template <int D, class GradientSet>
Mat<D> incrementalGradient(std::size_t a, const std::vector<Vec<D>>& x,
                           const ReferenceConfiguration<D>& ref, const GradientSet& gradients)
{
    const NeighbourList& list = ref.neighbours;
    Mat<D> sum = Mat<D>::Zero();
    const Vec<D> xa = x[a];
    const auto pairs = gradients.particle(a);
    for (std::size_t k = list.begin(a) + 1; k < list.end(a); ++k)
    {
        const std::size_t b = list.indices[k];
        sum.noalias() += (ref.V[b] * (x[b] - xa)) * pairs.outgoing(k).transpose();
    }
    return gradients.gradient().deformation(a, sum); // + C_a for a deficient support
}

// T_c = -V_c Σ_{a≠c} UL_a d_ac - UL_c e_c with UL_a = U_a L_a (spec §4 in gather form).
template <int D, class GradientSet>
Vec<D> gatherCsphForce(std::size_t c, const ReferenceConfiguration<D>& ref,
                       const GradientSet& gradients, const std::vector<Mat<D>>& UL)
{
    const NeighbourList& list = ref.neighbours;
    Vec<D> sum = Vec<D>::Zero();
    const auto pairs = gradients.particle(c);
    for (std::size_t k = list.begin(c) + 1; k < list.end(c); ++k)
    {
        sum.noalias() += UL[list.indices[k]] * pairs.incoming(k);
    }
    return -ref.V[c] * sum - UL[c] * gradients.e(c);
}

// Work split into chunks of particles of one body, so a chunk calls its material once.
struct ParticleChunk
{
    std::size_t body;
    std::size_t begin;
    std::size_t end;
};

inline std::vector<ParticleChunk> makeChunks(const std::vector<BodyRange>& bodies,
                                             std::size_t size = 64)
{
    std::vector<ParticleChunk> chunks;
    for (std::size_t b = 0; b < bodies.size(); ++b)
    {
        for (std::size_t i = bodies[b].begin; i < bodies[b].end; i += size)
        {
            chunks.push_back({b, i, std::min(bodies[b].end, i + size)});
        }
    }
    return chunks;
}

// The chunks of the current body ranges, made again whenever the ranges change (not only the
// particle count: a distributed run's local particles change at each migration, and the same
// count may split into other ranges).
class ChunkCache
{
public:
    const std::vector<ParticleChunk>& of(const std::vector<BodyRange>& bodies)
    {
        bool same = bodies.size() == ranges_.size();
        for (std::size_t b = 0; same && b < bodies.size(); ++b)
        {
            same = ranges_[b].first == bodies[b].begin && ranges_[b].second == bodies[b].end;
        }
        if (!same)
        {
            chunks_ = makeChunks(bodies);
            ranges_.clear();
            for (const BodyRange& range : bodies)
            {
                ranges_.emplace_back(range.begin, range.end);
            }
        }
        return chunks_;
    }

private:
    std::vector<ParticleChunk> chunks_;
    std::vector<std::pair<std::size_t, std::size_t>> ranges_;
};

// Per-chunk partial results, combined in chunk order (independent of the thread count).
struct ChunkTally
{
    double energy = 0.0;
    long badParticle = -1;
    double badValue = 0.0; // its det F

    // det F <= 0 (or not finite) at `particle`.
    void flagJacobian(std::size_t particle, double J)
    {
        if (badParticle < 0)
        {
            badParticle = static_cast<long>(particle);
            badValue = J;
        }
    }
};

inline ForceStatus combine(const std::vector<ChunkTally>& tallies)
{
    ForceStatus status;
    for (const ChunkTally& tally : tallies)
    {
        status.strainEnergy += tally.energy;
        if (status.ok() && tally.badParticle >= 0)
        {
            const double energy = status.strainEnergy;
            status = ForceStatus::failed(FailureKind::nonPositiveJacobian, tally.badParticle,
                                         tally.badValue, "det F");
            status.strainEnergy = energy;
        }
    }
    return status;
}

// det F must stay positive (and finite) for every hyperelastic model.
template <int D>
inline bool admissible(const Mat<D>& F, double& J)
{
    J = F.determinant();
    return J > 0.0 && std::isfinite(J);
}

// Flags the first particle (of those that count, see ForceInput::owned) whose force is not
// finite.
template <int D>
void checkForces(const std::vector<Vec<D>>& T, ForceStatus& status,
                 const std::vector<std::uint8_t>* owned = nullptr)
{
    if (!status.ok())
    {
        return;
    }
    for (std::size_t c = 0; c < T.size(); ++c)
    {
        if (!T[c].allFinite() && (!owned || (*owned)[c]))
        {
            status = ForceStatus::failed(FailureKind::nonFiniteForce, static_cast<long>(c),
                                         T[c].norm(), "internal force");
            return;
        }
    }
}

} // namespace sph

namespace sph
{

// Plain CSPH with a given gradient set: F_a = f_a F^r_a, P_a = P(F_a), Π = Σ V0_a Ψ(F_a),
// T_c = -Σ_a V0_a P_a F^r_a^T g_a(c). The `none` scheme with the standard gradient, the
// `vidal` scheme with the shifted one, and `hourglass` on top of it.
template <int D>
class CsphCore
{
public:
    // F for every particle at positions x (no stress); flags det F <= 0.
    template <class GradientSet>
    ForceStatus deformationGradients(const std::vector<Vec<D>>& x,
                                     const ReferenceConfiguration<D>& ref,
                                     const GradientSet& gradients, std::vector<Mat<D>>& F) const
    {
        const std::size_t n = ref.size();
        F.resize(n);
        long bad = -1;
        double badJ = 0.0;
#pragma omp parallel for schedule(static) if (useThreads(n))
        for (std::size_t a = 0; a < n; ++a)
        {
            F[a] = incrementalGradient<D>(a, x, ref, gradients) * ref.F[a];
        }
        for (std::size_t a = 0; a < n && bad < 0; ++a)
        {
            if (ref.counts(a) && !admissible<D>(F[a], badJ))
            {
                bad = static_cast<long>(a);
            }
        }
        return bad < 0 ? ForceStatus{}
                       : ForceStatus::failed(FailureKind::nonPositiveJacobian, bad, badJ, "det F");
    }

    // f (the incremental gradient) is stored in *fOut when given (hourglass control uses it).
    template <class GradientSet>
    ForceStatus compute(const ForceInput<D>& in, ForceOutput<D>& out, bool wantEnergy,
                        const GradientSet& gradients, std::vector<Mat<D>>* fOut = nullptr)
    {
        const std::size_t n = in.ref.size();
        out.T.resize(n);
        out.F.resize(n);
        out.P.resize(n);
        UL_.resize(n);
        if (fOut)
        {
            fOut->resize(n);
        }
        const std::vector<ParticleChunk>& chunks = chunkCache_.of(in.bodies);
        std::vector<ChunkTally> tallies(chunks.size());
#pragma omp parallel if (useThreads(n))
        {
            std::vector<double> psi;
#pragma omp for schedule(static)
            for (std::size_t i = 0; i < chunks.size(); ++i)
            {
                const ParticleChunk& chunk = chunks[i];
                ChunkTally& tally = tallies[i];
                for (std::size_t a = chunk.begin; a < chunk.end; ++a)
                {
                    const Mat<D> f = in.atReference
                                         ? Mat<D>::Identity()
                                         : incrementalGradient<D>(a, in.x, in.ref, gradients);
                    if (fOut)
                    {
                        (*fOut)[a] = f;
                    }
                    out.F[a] = f * in.ref.F[a];
                    double J;
                    if (!admissible<D>(out.F[a], J))
                    {
                        if (in.counts(a))
                        {
                            tally.flagJacobian(a, J);
                        }
                        out.F[a].setIdentity(); // keep the arithmetic finite; the run stops
                    }
                }
                const std::size_t count = chunk.end - chunk.begin;
                psi.resize(count);
                in.materials[chunk.body]->evaluate(&out.F[chunk.begin], &out.P[chunk.begin],
                                                   wantEnergy ? psi.data() : nullptr, count,
                                                   HistoryOf::particles(chunk.begin));
                for (std::size_t a = chunk.begin; a < chunk.end; ++a)
                {
                    UL_[a] = in.V0[a] * out.P[a] * in.ref.F[a].transpose() * gradients.L(a);
                    if (wantEnergy && in.counts(a))
                    {
                        tally.energy += in.V0[a] * psi[a - chunk.begin];
                    }
                }
            }
#pragma omp for schedule(static)
            for (std::size_t c = 0; c < n; ++c)
            {
                out.T[c] = gatherCsphForce<D>(c, in.ref, gradients, UL_);
            }
        }
        ForceStatus status = combine(tallies);
        checkForces<D>(out.T, status, in.owned);
        return status;
    }

    template <class GradientSet>
    double energy(const ForceInput<D>& in, const GradientSet& gradients)
    {
        std::vector<Mat<D>> F;
        deformationGradients(in.x, in.ref, gradients, F);
        double total = 0.0;
        for (std::size_t b = 0; b < in.bodies.size(); ++b)
        {
            const BodyRange& range = in.bodies[b];
            const Material<D>& material = *in.materials[b];
            for (std::size_t a = range.begin; a < range.end; ++a)
            {
                if (!in.counts(a))
                {
                    continue; // a ghost: its owner counts it
                }
                Mat<D> P;
                double psi;
                material.evaluate(&F[a], &P, &psi, 1, HistoryOf::particles(a));
                total += in.V0[a] * psi;
            }
        }
        return total;
    }

private:
    std::vector<Mat<D>> UL_; // V0_a P_a F^r_a^T L_a
    ChunkCache chunkCache_;
};

} // namespace sph
