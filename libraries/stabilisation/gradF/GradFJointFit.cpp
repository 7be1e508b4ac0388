// gradF with `fit joint` (docs/theory/gradF-plastic.md §G17): f_a and H_a from one weighted
// least-squares fit of the second-order Taylor expansion, (G17.2), and particle a's terms of its
// force (G17.3); the force's gather is in GradF.cpp beside the sequential fit's.
#include "stabilisation/gradF/GradF.hpp"
#include "stabilisation/gradF/MonomialTensors.hpp"
#include "stabilisation/gradF/RegularisedInverse.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace sph
{

// A_a = [[Mxx, Yᵀ], [Y, Z]] over p = (x^r, z), Mxx = Σ Ŵ x^r ⊗ x^r, inverted by blocks through
// the Schur complement Zs = Z − Y Mxx⁻¹ Yᵀ (the spread of the curvatures the linear term does
// not explain): with Zs⁻¹ regularised as Z⁻¹ is (its eigenvalues judged against Z's mean, raised
// to 0.02 of it), c_a = (R_z − R_x Mxx⁻¹ Yᵀ) Zs⁻¹ vanishes for every linear motion and f_a is then
// exact, whatever the regularisation did; a well-conditioned Zs gives the exact inverse.
// A singular support (the neighbours span no volume: a particle alone, a chain, a flat layer)
// is completed as the corrected gradient completes one (CorrectedGradient.hpp): the eigenvalues
// of Mxx / ℓ² (mean 1, ℓ² = tr Mxx / D) below singularEigenvalue raised to it, and f_a completed
// with the part of the identity the fit cannot see, C_a = I − Mxx Mxx'⁻¹, so that f_a = I at the
// reference and for a particle with no neighbour; C_a is constant in a reference period, so the
// force stays the exact −∂Π/∂x. Only a singular support: raising the eigenvalues to 0.02, as the
// corrected gradient does, made the Taylor bar fail at 35 µs (§G18: rim particles squeezed along
// the wall have nearly flat supports, eigenvalues of a few thousandths, whose exact inverse the
// run needs). Returns C_a (zero for a full support).
template <int D>
Mat<D> GradF<D>::invertJointMatrix(const Mat<D>& Mxx, const MatMD& Y, const MatM& Z,
                                   MatP& Ainv) const
{
    const double ell2 = Mxx.trace() / D;
    const double scale = Z.trace() / M;
    if (!(ell2 > 0.0) || !(scale > 0.0) || !Mxx.allFinite() || !Z.allFinite())
    {
        Ainv.setZero();
        return Mat<D>::Identity(); // no neighbour: f_a = I, H_a = 0
    }
    Mat<D> MxxInv;
    Mat<D> complement = Mat<D>::Zero();
    const Eigen::SelfAdjointEigenSolver<Mat<D>> eigen(Mxx / ell2);
    // Where the corrected gradient reports a singular M (CorrectedGradient.hpp: det below 1e-8).
    constexpr double singularEigenvalue = 1.0e-8;
    if (eigen.eigenvalues()[0] >= singularEigenvalue) // ascending
    {
        MxxInv = Mxx.inverse();
    }
    else
    {
        Vec<D> inverse;
        Vec<D> unseen;
        for (int i = 0; i < D; ++i)
        {
            const double lambda = std::max(eigen.eigenvalues()[i], 0.0);
            inverse[i] = 1.0 / std::max(lambda, singularEigenvalue);
            unseen[i] = 1.0 - lambda * inverse[i];
        }
        MxxInv = eigen.eigenvectors() * (inverse / ell2).asDiagonal() *
                 eigen.eigenvectors().transpose();
        complement = eigen.eigenvectors() * unseen.asDiagonal() * eigen.eigenvectors().transpose();
    }
    const MatMD YM = Y * MxxInv; // Y Mxx⁻¹
    const MatM Zs = Z - YM * Y.transpose();
    const MatM ZsInv = regularisedInverse(MatM(0.5 * (Zs + Zs.transpose())), scale,
                                          smallestEigenvalue);
    Ainv.template topLeftCorner<D, D>() = MxxInv + YM.transpose() * ZsInv * YM;
    Ainv.template topRightCorner<D, M>() = -YM.transpose() * ZsInv;
    Ainv.template bottomLeftCorner<M, D>() = -ZsInv * YM;
    Ainv.template bottomRightCorner<M, M>() = ZsInv;
    return complement;
}

// [f_a | c_a] = R A_a⁻¹ with R = Σ_b Ŵ_ab x_ba ⊗ p_ab, p_ab = (x^r_ba, z_ab), and f_a completed
// with C_a.
template <int D>
void GradF<D>::jointKinematics(std::size_t a, const std::vector<Vec<D>>& x,
                               const ReferenceConfiguration<D>& ref, Scratch& scratch,
                               Kinematics& kin) const
{
    const NeighbourList& list = ref.neighbours;
    const std::size_t first = list.begin(a);
    const std::size_t count = list.count(a);
    const Vec<D> xra = ref.x[a];
    const Vec<D> xa = x[a];
    const double invDenominator = invDenominator_[a];
    const double* W = ref.kernelValues(a).W; // W[j] for the j-th neighbour
    MatDP R = MatDP::Zero();
    for (std::size_t j = 1; j < count; ++j)
    {
        const std::size_t b = list.indices[first + j];
        const Vec<D> xr = ref.x[b] - xra;
        const double w = W[j] * ref.V[b] * invDenominator;
        scratch.xr[j] = xr;
        scratch.w[j] = w;
        const Vec<D> wxba = w * (x[b] - xa);
        R.template leftCols<D>().noalias() += wxba * xr.transpose();
        R.template rightCols<M>().noalias() += wxba * monomials<D>(xr).transpose();
    }
    const MatDP fc = R * Ainv_[a];
    kin.f = fc.template leftCols<D>() + jointComplement_[a];
    kin.H = hessianFromCoefficients<D>(MatDM(fc.template rightCols<M>()));
}

// N_a = V0_a E_a A_a⁻¹, E_a = [A_a | B~_a]; T_c gathers −V^r_c W_ac (N_a,c z − N_a,f x^r) / Σ W V
// over its neighbours a and N_c r_c, r_c = (Σ_e Ŵ_ce x^r_ec, s_c), for itself (GradF.cpp).
template <int D>
void GradF<D>::jointForceTerms(std::size_t a, double V0, const Mat<D>& A, const Tensor3<D>& B)
{
    MatDP E;
    E.template leftCols<D>() = A;
    E.template rightCols<M>() = contractMonomials<D, MatDM>(B);
    const MatDP N = V0 * (E * Ainv_[a]);
    UL_[a] = invDenominator_[a] * N.template leftCols<D>();
    Cw_[a] = invDenominator_[a] * N.template rightCols<M>();
    selfTerm_[a] = N.template leftCols<D>() * firstMoment_[a] + N.template rightCols<M>() * s_[a];
}

template Mat<1> GradF<1>::invertJointMatrix(const Mat<1>&, const MatMD&, const MatM&, MatP&) const;
template Mat<2> GradF<2>::invertJointMatrix(const Mat<2>&, const MatMD&, const MatM&, MatP&) const;
template Mat<3> GradF<3>::invertJointMatrix(const Mat<3>&, const MatMD&, const MatM&, MatP&) const;
template void GradF<1>::jointKinematics(std::size_t, const std::vector<Vec<1>>&,
                                        const ReferenceConfiguration<1>&, Scratch&,
                                        Kinematics&) const;
template void GradF<1>::jointForceTerms(std::size_t, double, const Mat<1>&, const Tensor3<1>&);
template void GradF<2>::jointKinematics(std::size_t, const std::vector<Vec<2>>&,
                                        const ReferenceConfiguration<2>&, Scratch&,
                                        Kinematics&) const;
template void GradF<2>::jointForceTerms(std::size_t, double, const Mat<2>&, const Tensor3<2>&);
template void GradF<3>::jointKinematics(std::size_t, const std::vector<Vec<3>>&,
                                        const ReferenceConfiguration<3>&, Scratch&,
                                        Kinematics&) const;
template void GradF<3>::jointForceTerms(std::size_t, double, const Mat<3>&, const Tensor3<3>&);

} // namespace sph
