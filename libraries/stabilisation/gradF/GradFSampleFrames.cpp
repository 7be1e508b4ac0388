// gradF's elasticState samples in total-Lagrangian form (docs/theory/gradF-plastic.md §G25-§G26):
// the samples of the step's increment in their particle's frame (G26.1), its gradient fitted
// there (G26.2), and the frames moved at each commit with every sample's elastic state kept.
// The frames themselves are SampleFrames.hpp; the force (G26.3) is GradF.cpp's.
#include "stabilisation/gradF/GradF.hpp"
#include "stabilisation/gradF/MonomialTensors.hpp"
#include "stabilisation/gradF/RegularisedInverse.hpp"

#include <stdexcept>

namespace sph
{

// (G26.2): H°_a by least squares in the frame's configuration with the increment f_a = F_a F°_a⁻¹
// fixed, as the paper fits H_a with f_a fixed (spec §6.2), over the same list and weights:
// c°_a = [Σ_b Ŵ_ab x_ba ⊗ z(y°_ab) − f_a Y°_aᵀ] Z°_a⁻¹. In the first step (x° = X, F° = I) these
// are the paper's sums in the paper's order, so the samples are its samples bit for bit.
template <int D>
void GradF<D>::fillFramedSamples(std::size_t a, const std::vector<Vec<D>>& x,
                                 const NeighbourList& list, const Kinematics& kin,
                                 Scratch& scratch) const
{
    typename Scratch::FrameFit& fit = scratch.frame;
    const std::size_t first = list.begin(a);
    const std::size_t count = list.count(a);
    frames_.offsets(a, list, scratch.xr.data());
    MatM Z = MatM::Zero();
    MonomialVec<D> s = MonomialVec<D>::Zero();
    MatMD Y = MatMD::Zero();
    Mat<D> Mxx = Mat<D>::Zero(); // fit joint
    Vec<D> moment = Vec<D>::Zero();
    MatDP R = MatDP::Zero(); // Σ_b Ŵ_ab x_ba ⊗ p°_ab (sequential: its monomial columns only)
    const Vec<D> xa = x[a];
    for (std::size_t j = 1; j < count; ++j)
    {
        const Vec<D>& y = scratch.xr[j];
        const MonomialVec<D> z = monomials<D>(y);
        const double w = scratch.w[j];
        Z.noalias() += w * z * z.transpose();
        s += w * z;
        Y.noalias() += w * z * y.transpose();
        const Vec<D> wxba = w * (x[list.indices[first + j]] - xa);
        if (jointFit_)
        {
            Mxx.noalias() += (w * y) * y.transpose();
            moment += w * y;
            R.template leftCols<D>().noalias() += wxba * y.transpose();
        }
        R.template rightCols<M>().noalias() += wxba * z.transpose();
    }
    fit.s = s;
    fit.inverseFrameF = frames_.frameF(a).inverse();
    if (jointFit_)
    {
        // (G26.4): f and H° of the increment from one fit in x°, as (G17.2) in x^r.
        invertJointMatrix(Mxx, Y, Z, fit.Ainv);
        fit.moment = moment;
        const MatDP fc = R * fit.Ainv;
        fit.H = hessianFromCoefficients<D>(MatDM(fc.template rightCols<M>()));
    }
    else
    {
        fit.Zinv = regularisedInverse(Z, Z.trace() / M, smallestEigenvalue);
        fit.Y = Y;
        const Mat<D> f = kin.F * fit.inverseFrameF;
        fit.H = hessianFromCoefficients<D>(
            MatDM((R.template rightCols<M>() - f * Y.transpose()) * fit.Zinv));
    }
    frames_.samples(a, kin.F, fit.H, scratch.xr.data(), count, scratch.F.data());
}

// δΠ_a through H°_a: with B~°_a = [Σ_b Ŵ_ab y°_ab,k P_b F°_aᵀ] in the monomials' columns and
// C°_a = B~°_a Z°_a⁻¹, δΠ_a = V0_a C°_a : [Σ_b Ŵ_ab δx_ba ⊗ z(y°_ab) − δF_a F°_a⁻¹ Y°_aᵀ], so
// ∂Π/∂F_a gains −V0_a C°_a Y°_a F°_a⁻ᵀ and the pairs V0_a C°_a z(y°_ab), as the paper's C_a takes
// z(x^r_ab) (spec §6.4).
template <int D>
void GradF<D>::frameForceTerms(std::size_t a, double V0, const typename Scratch::FrameFit& fit,
                               Mat<D>& A, Tensor3<D>& B, Vec<D>& selfTerm)
{
    const Mat<D> frameFT = frames_.frameF(a).transpose();
    for (std::size_t k = 0; k < static_cast<std::size_t>(D); ++k)
    {
        B.slice[k] = B.slice[k] * frameFT;
    }
    if (jointFit_)
    {
        // (G26.5): H° depends on x through the pairs only, N°_a = V0_a [0 | B~°_a] A°_a⁻¹.
        MatDP E = MatDP::Zero();
        E.template rightCols<M>() = contractMonomials<D, MatDM>(B);
        const MatDP N = V0 * (E * fit.Ainv);
        frameUL_[a] = invDenominator_[a] * N.template leftCols<D>();
        frameCw_[a] = invDenominator_[a] * N.template rightCols<M>();
        selfTerm = N.template leftCols<D>() * fit.moment + N.template rightCols<M>() * fit.s;
    }
    else
    {
        const MatDM C = contractMonomials<D, MatDM>(B) * fit.Zinv;
        A.noalias() -= C * fit.Y * fit.inverseFrameF.transpose();
        frameCw_[a] = (V0 * invDenominator_[a]) * C;
        selfTerm = V0 * (C * fit.s);
    }
    B = Tensor3<D>::zero();
}

// After the commit of the last evaluation's states: each sample's state re-expressed at the
// evaluation's F_a, Cp⁻¹ ← N Cp⁻¹ Nᵀ with N = F_a⁻¹ F_b(a) (G4.1), so that its be does not
// change, and the frames moved to that evaluation. Every sample keeps a record from then on.
template <int D>
void GradF<D>::moveSampleFrames(const HistoryCommit<D>& in)
{
    if (!framedList_)
    {
        throw std::logic_error("gradF: a commit before any force evaluation (§G25 frames)");
    }
    const NeighbourList& list = *framedList_;
    const std::size_t n = list.particleCount();
    if (!frames_.hasEvaluation(n))
    {
        throw std::logic_error("gradF: the frames' evaluation is not of the committed particles");
    }
    std::vector<int> body(n, -1);
    for (std::size_t b = 0; b < in.bodies.size(); ++b)
    {
        for (std::size_t a = in.bodies[b].begin; a < in.bodies[b].end; ++a)
        {
            body[a] = static_cast<int>(b);
        }
    }
    samples_.storeEveryState(body, in.materials);
#pragma omp parallel if (useThreads(n))
    {
        Scratch scratch;
        scratch.resize(maxNeighbours_);
#pragma omp for schedule(static)
        for (std::size_t a = 0; a < n; ++a)
        {
            const Material<D>* material = in.materials[static_cast<std::size_t>(body[a])];
            if (!material || !material->hasHistory())
            {
                continue;
            }
            const std::size_t count = list.count(a);
            frames_.offsets(a, list, scratch.xr.data());
            frames_.samples(a, frames_.evaluatedF(a), frames_.evaluatedH(a), scratch.xr.data(),
                            count, scratch.F.data());
            scratch.states.resize(count * samples_.stride());
            samples_.rebase(list.begin(a), count, *material, scratch.F.data(),
                            frames_.evaluatedF(a), scratch.states.data());
        }
    }
    frames_.move();
}

template void GradF<1>::fillFramedSamples(std::size_t, const std::vector<Vec<1>>&,
                                          const NeighbourList&, const Kinematics&, Scratch&) const;
template void GradF<2>::fillFramedSamples(std::size_t, const std::vector<Vec<2>>&,
                                          const NeighbourList&, const Kinematics&, Scratch&) const;
template void GradF<3>::fillFramedSamples(std::size_t, const std::vector<Vec<3>>&,
                                          const NeighbourList&, const Kinematics&, Scratch&) const;
template void GradF<1>::frameForceTerms(std::size_t, double, const Scratch::FrameFit&, Mat<1>&,
                                        Tensor3<1>&, Vec<1>&);
template void GradF<2>::frameForceTerms(std::size_t, double, const Scratch::FrameFit&, Mat<2>&,
                                        Tensor3<2>&, Vec<2>&);
template void GradF<3>::frameForceTerms(std::size_t, double, const Scratch::FrameFit&, Mat<3>&,
                                        Tensor3<3>&, Vec<3>&);
template void GradF<1>::moveSampleFrames(const HistoryCommit<1>&);
template void GradF<2>::moveSampleFrames(const HistoryCommit<2>&);
template void GradF<3>::moveSampleFrames(const HistoryCommit<3>&);

} // namespace sph
