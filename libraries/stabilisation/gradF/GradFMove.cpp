// gradF's moves of the reference configuration: referenceUpdate() (F^r and K) and, with
// plasticSamples elasticState (docs/theory/gradF-plastic.md), what a move does to the samples'
// states and the particles' own, and the energy weights the move chooses (§G9). The samples'
// evaluation and commit are those of every per-sample history (GradFHistory.cpp); the frame
// F^r = J^(1/D) I and K = 0 are set by referenceUpdate (below) for the particles marked here.
#include "stabilisation/gradF/EnergyWeights.hpp"
#include "stabilisation/gradF/GradF.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sph
{

// elasticState (docs/theory/gradF-plastic.md §G4): with the old reference still in place, each
// sample's state and the particle's own are re-expressed against the new reference gradient,
// the dilation F^r_a = J_a^(1/D) I, so that their be at the current positions does not change
// (G4.1); the referenceUpdate() that follows sets that F^r_a and K_a = 0 for these particles.
template <int D>
void GradF<D>::moveHistory(const std::vector<Vec<D>>& x, const ReferenceConfiguration<D>& ref,
                           const std::vector<int>& body, const std::vector<Material<D>*>& materials)
{
    if (!elasticState_ || !samples_.active())
    {
        return;
    }
    const NeighbourList& list = ref.neighbours;
    const std::size_t n = ref.size();
    if (!samples_.current())
    {
        throw std::logic_error("gradF: the reference moves before the samples' states follow its "
                               "list (a move must come after a force evaluation)");
    }
    spatialFrame_.assign(n, 0);
    weightsDue_ = samples_.weighted(); // the evaluation after the move chooses them (§G9)
    // det f_b(a) = det F_b(a) / det F_a^r of each particle's most inverted sample, 1 if none
    // (§G3: none unless the step was unstable). be = F Cp⁻¹ Fᵀ is positive definite for det F < 0
    // too, so an inverted sample would carry on as its mirror image: the move refuses it instead.
    std::vector<double> inverted(n, 1.0);
    movedFrames_.assign(n, 0.0);
    movedFramesAt_ = x.data();
    samples_.storeEveryState(body, materials); // none stays the initial one
    if (moments_.carriesStates())
    {
        moments_.startMove(n); // the points turn with the material (§M7)
    }
#pragma omp parallel if (useThreads(n))
    {
        Scratch scratch;
        scratch.resize(maxNeighbours_);
#pragma omp for schedule(static)
        for (std::size_t a = 0; a < n; ++a)
        {
            Material<D>& material = *materials[static_cast<std::size_t>(body[a])];
            if (!material.hasHistory())
            {
                continue;
            }
            spatialFrame_[a] = 1;
            const Kinematics kin = kinematics(a, x, ref, false, scratch);
            movedFrames_[a] = std::pow(kin.F.determinant(), 1.0 / D);
            const Mat<D> frame = movedFrames_[a] * Mat<D>::Identity();
            // The samples: the neighbours', or the moment points' (§M7).
            const std::size_t count = moments_.use(a, list.count(a), scratch.xr.data(),
                                                   scratch.w.data(), moments_.carriesStates());
            if (moments_.carriesStates())
            {
                moments_.follow(a, kin.f);
            }
            const double Jr = ref.F[a].determinant();
            const double smallest = fillSamples(kin, count, scratch, particleVolume_, true) / Jr;
            if (!(smallest > 0.0))
            {
                inverted[a] = smallest;
            }
            scratch.states.resize(count * samples_.stride());
            samples_.rebase(samples_.begin(a), count, material, scratch.F.data(), frame,
                            scratch.states.data());
            material.rebaseParticleHistory(a, kin.F, frame);
        }
    }
    openingDissipation_.assign(openedFromParticle_ ? n : 0, 0.0);
    if (openedFromParticle_)
    {
        takeOpenedStates(x, ref, body, materials);
    }
    sampleInversion_ = ForceStatus();
    for (std::size_t a = 0; a < n; ++a)
    {
        if (ref.counts(a) && !(inverted[a] > 0.0))
        {
            sampleInversion_ = ForceStatus::failed(
                FailureKind::nonPositiveJacobian, static_cast<long>(a), inverted[a],
                "det f_b(a) of a stress sample (gradF elasticState, the step's motion across "
                "the kernel)");
            break;
        }
    }
}

// The move itself: F^r = f F^r at x (and, for the paper's samples, K' = G f⁻¹); for the particles
// marked by moveHistory() the dilation frame it computed.
template <int D>
ForceStatus GradF<D>::referenceUpdate(const std::vector<Vec<D>>& x,
                                      const ReferenceConfiguration<D>& ref, std::vector<Mat<D>>& F,
                                      std::vector<Tensor3<D>>* newK) const
{
    const std::size_t n = ref.size();
    F.resize(n);
    if (newK)
    {
        newK->resize(n);
    }
    // The frames moveHistory() computed at these positions, if it was called just before
    // (taken once: a later call computes its own).
    const bool handed = movedFramesAt_ == x.data() && movedFrames_.size() == n;
    movedFramesAt_ = nullptr;
#pragma omp parallel if (useThreads(n))
    {
    Scratch scratch;
    scratch.resize(maxNeighbours_);
#pragma omp for schedule(static)
    for (std::size_t a = 0; a < n; ++a)
    {
        const bool spatial = a < spatialFrame_.size() && spatialFrame_[a];
        if (spatial && handed)
        {
            // elasticState (§G4), the frame as moveHistory() found it.
            F[a] = movedFrames_[a] * Mat<D>::Identity();
            if (newK)
            {
                (*newK)[a] = Tensor3<D>::zero();
            }
            continue;
        }
        const Kinematics kin = kinematics(a, x, ref, false, scratch);
        F[a] = kin.F;

        if (spatial)
        {
            // elasticState (§G4): the samples carry the gradient, the states the shape.
            F[a] = std::pow(kin.F.determinant(), 1.0 / D) * Mat<D>::Identity();
            if (newK)
            {
                (*newK)[a] = Tensor3<D>::zero();
            }
        }
        else if (newK)
        {
            // K' = G f^{-1} on the derivative index: K'_ijk = G_ijl (f^{-1})_lk (spec §6.5).
            const Mat<D> finv = kin.f.inverse();
            for (int k = 0; k < D; ++k)
            {
                Mat<D> slice = Mat<D>::Zero();
                for (int l = 0; l < D; ++l)
                {
                    slice += kin.G.slice[static_cast<std::size_t>(l)] * finv(l, k);
                }
                (*newK)[a].slice[static_cast<std::size_t>(k)] = slice;
            }
        }
    }
    }
    ForceStatus status;
    for (std::size_t a = 0; a < n; ++a)
    {
        double J;
        if (ref.counts(a) && !admissible<D>(F[a], J))
        {
            status = ForceStatus::failed(FailureKind::nonPositiveJacobian, static_cast<long>(a), J,
                                         "det F");
            break;
        }
    }
    return status.ok() ? sampleInversion_ : status;
}

// moveWeights (§G9). The samples' energy E_a before the move = Σ_kept ω_ab W_ab (their W is
// unchanged by the move, G4.1) + Σ_left ω_ab W_ab (the pairs that left, from their rebased
// states at F^r_a); new pairs had ω = 0.
template <int D>
double GradF<D>::useEnergyWeights(std::size_t a, const Material<D>& material, std::size_t count,
                                  const Mat<D>& Fr, bool keep, Scratch& scratch)
{
    double* kept = &samples_.weight(samples_.begin(a));
    double* omega = scratch.omega.data();
    double residual = 0.0;
    if (std::isnan(kept[0])) // a first layout: the kernel's
    {
        std::copy(scratch.w.begin(), scratch.w.begin() + static_cast<long>(count), omega);
    }
    else if (weightsDue_)
    {
        double before = 0.0;
        for (std::size_t j = 0; j < count; ++j)
        {
            before += kept[j] * scratch.psi[j];
        }
        const std::size_t left = samples_.leavingCount(a);
        if (left > 0)
        {
            std::vector<Mat<D>> F(left, Fr);
            std::vector<Mat<D>> P(left);
            std::vector<double> psi(left);
            material.evaluate(F.data(), P.data(), psi.data(), left,
                              HistoryOf::samples(samples_.leavingStates(a), samples_.stride()));
            const double* leftWeights = samples_.leavingWeights(a);
            for (std::size_t i = 0; i < left; ++i)
            {
                before += leftWeights[i] * psi[i];
            }
        }
        const bool nonIncreasing = weights_ == MoveWeights::nonIncreasing;
        // Energies below that of a strain of one ulp are zero to the material (§G22): samples
        // that hold only such round-off (opened ones) keep the kernel's weights, not weights
        // set by their round-off.
        const double epsilon = std::numeric_limits<double>::epsilon();
        const double resolution = material.youngsModulus() * epsilon * epsilon;
        EnergyWeightsResult chosen = chooseEnergyWeights(scratch.w.data(), scratch.psi.data(),
                                                         count, before, nonIncreasing, omega,
                                                         resolution);
        if (!chosen.reached)
        {
            // Out of reach of the kernel's support: widen the base to the pairs the old
            // weights used, ½ (Ŵ' + ω) (§G9).
            std::vector<double> base(count);
            double sum = 0.0;
            for (std::size_t j = 0; j < count; ++j)
            {
                base[j] = 0.5 * (scratch.w[j] + kept[j]);
                sum += base[j];
            }
            for (double& value : base)
            {
                value /= sum;
            }
            chosen = chooseEnergyWeights(base.data(), scratch.psi.data(), count, before,
                                         nonIncreasing, omega, resolution);
        }
        residual = chosen.residual;
    }
    else
    {
        std::copy(kept, kept + count, omega);
    }
    if (keep)
    {
        std::copy(omega, omega + count, kept);
    }
    std::copy(omega, omega + count, scratch.w.begin());
    return residual;
}

// GradF<D> is instantiated in GradF.cpp; these members are defined here.
template ForceStatus GradF<1>::referenceUpdate(const std::vector<Vec<1>>&,
                                               const ReferenceConfiguration<1>&,
                                               std::vector<Mat<1>>&, std::vector<Tensor3<1>>*) const;
template ForceStatus GradF<2>::referenceUpdate(const std::vector<Vec<2>>&,
                                               const ReferenceConfiguration<2>&,
                                               std::vector<Mat<2>>&, std::vector<Tensor3<2>>*) const;
template ForceStatus GradF<3>::referenceUpdate(const std::vector<Vec<3>>&,
                                               const ReferenceConfiguration<3>&,
                                               std::vector<Mat<3>>&, std::vector<Tensor3<3>>*) const;
template double GradF<1>::useEnergyWeights(std::size_t, const Material<1>&, std::size_t,
                                             const Mat<1>&, bool, Scratch&);
template void GradF<1>::moveHistory(const std::vector<Vec<1>>&, const ReferenceConfiguration<1>&,
                                     const std::vector<int>&, const std::vector<Material<1>*>&);
template double GradF<2>::useEnergyWeights(std::size_t, const Material<2>&, std::size_t,
                                             const Mat<2>&, bool, Scratch&);
template void GradF<2>::moveHistory(const std::vector<Vec<2>>&, const ReferenceConfiguration<2>&,
                                     const std::vector<int>&, const std::vector<Material<2>*>&);
template double GradF<3>::useEnergyWeights(std::size_t, const Material<3>&, std::size_t,
                                             const Mat<3>&, bool, Scratch&);
template void GradF<3>::moveHistory(const std::vector<Vec<3>>&, const ReferenceConfiguration<3>&,
                                     const std::vector<int>&, const std::vector<Material<3>*>&);

} // namespace sph
