// gradF's kinematics (spec §6.1-6.2): f_a, F_a = f_a F^r_a and G_a = H_a F^r_a + f_a K_a of a
// particle from its neighbours, by the paper's sequential fit or the joint one (§G17,
// GradFJointFit.cpp). The energy and the force are GradF.cpp.
#include "stabilisation/gradF/GradF.hpp"
#include "stabilisation/gradF/MonomialTensors.hpp"

namespace sph
{

template <int D>
typename GradF<D>::Kinematics GradF<D>::kinematics(std::size_t a, const std::vector<Vec<D>>& x,
                                                   const ReferenceConfiguration<D>& ref) const
{
    Scratch scratch;
    scratch.resize(ref.neighbours.count(a));
    return kinematics(a, x, ref, false, scratch);
}

template <int D>
typename GradF<D>::Kinematics GradF<D>::kinematics(std::size_t a, const std::vector<Vec<D>>& x,
                                                   const ReferenceConfiguration<D>& ref,
                                                   bool atReference, Scratch& scratch) const
{
    const NeighbourList& list = ref.neighbours;
    const std::size_t first = list.begin(a);
    const std::size_t count = list.count(a);
    const Vec<D> xra = ref.x[a];
    const double invDenominator = invDenominator_[a];
    const typename ReferenceConfiguration<D>::PairKernelValues values = ref.kernelValues(a);
    Kinematics kin;
    if (atReference)
    {
        for (std::size_t j = 0; j < count; ++j)
        {
            const std::size_t b = list.indices[first + j];
            scratch.xr[j] = ref.x[b] - xra;
            scratch.w[j] = values.W[j] * ref.V[b] * invDenominator;
        }
        kin.f.setIdentity();
        kin.F = ref.F[a];
        kin.H = Tensor3<D>::zero();
        kin.G = ref.K.empty() ? Tensor3<D>::zero() : ref.K[a];
        return kin;
    }
    scratch.xr[0].setZero();
    scratch.w[0] = values.W[0] * ref.V[a] * invDenominator;
    if (jointFit_)
    {
        jointKinematics(a, x, ref, scratch, kin); // (G17.2)
    }
    else
    {
        // One pass over the neighbours for both f_a (spec §2) and the least-squares right-hand
        // side Σ_b Ŵ_ab y_ab z_ab^T with y_ab = x_ba - f_a x^r_ba, which splits as
        // Σ_b Ŵ_ab x_ba z_ab^T - f_a Y_a^T (Y_a = Σ_b Ŵ_ab z_ab ⊗ x^r_ba is precomputed).
        Mat<D> moment = Mat<D>::Zero();
        MatDM Rx = MatDM::Zero();
        const Vec<D> xa = x[a];
        for (std::size_t j = 1; j < count; ++j)
        {
            const std::size_t b = list.indices[first + j];
            const Vec<D> xr = ref.x[b] - xra;
            const double w = values.W[j] * ref.V[b] * invDenominator;
            scratch.xr[j] = xr;
            scratch.w[j] = w;
            const Vec<D> xba = x[b] - xa;
            moment.noalias() -= (ref.V[b] * values.dWdrOverR[j] * xba) * xr.transpose(); // ∇W_ab = -W'/r x^r_ba
            Rx.noalias() += (w * xba) * monomials<D>(xr).transpose();
        }
        kin.f = ref.gradient.deformation(a, moment);
        // Least squares for ½H: c_a = [Σ_b Ŵ_ab y_ab z_ab^T] Z_a^{-1}.
        const MatDM c = (Rx - kin.f * Y_[a].transpose()) * Zinv_[a];
        kin.H = hessianFromCoefficients<D>(c);
    }
    kin.F = kin.f * ref.F[a];
    // G[k] = H[k] F^r + f K[k]  (G_ijk = H_imk F^r_mj + f_im K_mjk)
    for (int k = 0; k < D; ++k)
    {
        const auto kk = static_cast<std::size_t>(k);
        kin.G.slice[kk] = kin.H.slice[kk] * ref.F[a];
        if (!ref.K.empty())
        {
            kin.G.slice[kk] += kin.f * ref.K[a].slice[kk];
        }
    }
    return kin;
}

// The f_a part of kinematics() alone (the same sums in the same order).
template <int D>
Mat<D> GradF<D>::deformationGradient(std::size_t a, const std::vector<Vec<D>>& x,
                                     const ReferenceConfiguration<D>& ref) const
{
    if (jointFit_)
    {
        return kinematics(a, x, ref).F; // f_a is the joint fit's, with H_a
    }
    const NeighbourList& list = ref.neighbours;
    Mat<D> moment = Mat<D>::Zero();
    const Vec<D> xa = x[a];
    const double* dWdrOverR = ref.kernelValues(a).dWdrOverR; // [k - begin] for slot k
    for (std::size_t k = list.begin(a) + 1; k < list.end(a); ++k)
    {
        const std::size_t b = list.indices[k];
        const Vec<D> xr = ref.x[b] - ref.x[a];
        const Vec<D> xba = x[b] - xa;
        moment.noalias() -= (ref.V[b] * dWdrOverR[k - list.begin(a)] * xba) * xr.transpose();
    }
    const Mat<D> f = ref.gradient.deformation(a, moment);
    return f * ref.F[a];
}

// GradF<D> is instantiated in GradF.cpp; these are its members defined here.
template typename GradF<1>::Kinematics GradF<1>::kinematics(std::size_t, const std::vector<Vec<1>>&,
                                                         const ReferenceConfiguration<1>&) const;
template typename GradF<1>::Kinematics GradF<1>::kinematics(std::size_t, const std::vector<Vec<1>>&,
                                                         const ReferenceConfiguration<1>&, bool,
                                                         Scratch&) const;
template Mat<1> GradF<1>::deformationGradient(std::size_t, const std::vector<Vec<1>>&,
                                              const ReferenceConfiguration<1>&) const;
template typename GradF<2>::Kinematics GradF<2>::kinematics(std::size_t, const std::vector<Vec<2>>&,
                                                         const ReferenceConfiguration<2>&) const;
template typename GradF<2>::Kinematics GradF<2>::kinematics(std::size_t, const std::vector<Vec<2>>&,
                                                         const ReferenceConfiguration<2>&, bool,
                                                         Scratch&) const;
template Mat<2> GradF<2>::deformationGradient(std::size_t, const std::vector<Vec<2>>&,
                                              const ReferenceConfiguration<2>&) const;
template typename GradF<3>::Kinematics GradF<3>::kinematics(std::size_t, const std::vector<Vec<3>>&,
                                                         const ReferenceConfiguration<3>&) const;
template typename GradF<3>::Kinematics GradF<3>::kinematics(std::size_t, const std::vector<Vec<3>>&,
                                                         const ReferenceConfiguration<3>&, bool,
                                                         Scratch&) const;
template Mat<3> GradF<3>::deformationGradient(std::size_t, const std::vector<Vec<3>>&,
                                              const ReferenceConfiguration<3>&) const;

} // namespace sph
