// gradF with `fit joint` (docs/theory/gradF-plastic.md §G17): f_a and H_a from one weighted
// least-squares fit of the second-order Taylor expansion, (G17.2). The force (G17.3) is in
// GradF.cpp beside the sequential fit's.
#include "stabilisation/gradF/GradF.hpp"
#include "stabilisation/gradF/MonomialTensors.hpp"
#include "stabilisation/gradF/RegularisedInverse.hpp"

#include <cmath>

namespace sph
{

// A_a = [[Mxx, Yᵀ], [Y, Z]] over p = (x^r, z), Mxx = Σ Ŵ x^r ⊗ x^r, inverted by blocks through
// the Schur complement Zs = Z − Y Mxx⁻¹ Yᵀ (the spread of the curvatures the linear term does
// not explain): with Zs⁻¹ regularised as Z⁻¹ is (its eigenvalues judged against Z's mean, raised
// to 0.02 of it), c_a = (R_z − R_x Mxx⁻¹ Yᵀ) Zs⁻¹ vanishes for every linear motion and f_a is then
// exact, whatever the regularisation did; a well-conditioned Zs gives the exact inverse.
template <int D>
bool GradF<D>::invertJointMatrix(const Mat<D>& Mxx, const MatMD& Y, const MatM& Z,
                                 MatP& Ainv) const
{
    const double scale = Z.trace() / M;
    const double detMxx = Mxx.determinant();
    if (!(scale > 0.0) || !(std::abs(detMxx) > 0.0) || !std::isfinite(detMxx))
    {
        Ainv.setZero();
        return false;
    }
    const Mat<D> MxxInv = Mxx.inverse();
    const MatMD YM = Y * MxxInv; // Y Mxx⁻¹
    const MatM Zs = Z - YM * Y.transpose();
    const MatM ZsInv = regularisedInverse(MatM(0.5 * (Zs + Zs.transpose())), scale,
                                          smallestEigenvalue);
    Ainv.template topLeftCorner<D, D>() = MxxInv + YM.transpose() * ZsInv * YM;
    Ainv.template topRightCorner<D, M>() = -YM.transpose() * ZsInv;
    Ainv.template bottomLeftCorner<M, D>() = -ZsInv * YM;
    Ainv.template bottomRightCorner<M, M>() = ZsInv;
    const double det = (Zs / scale).determinant();
    return det > 1.0e-12 && std::isfinite(det);
}

template <int D>
void GradF<D>::jointKinematics(const MatDP& R, std::size_t a, Kinematics& kin) const
{
    const MatDP fc = R * Ainv_[a];
    kin.f = fc.template leftCols<D>();
    kin.H = hessianFromCoefficients<D>(MatDM(fc.template rightCols<M>()));
}

template bool GradF<1>::invertJointMatrix(const Mat<1>&, const MatMD&, const MatM&, MatP&) const;
template bool GradF<2>::invertJointMatrix(const Mat<2>&, const MatMD&, const MatM&, MatP&) const;
template bool GradF<3>::invertJointMatrix(const Mat<3>&, const MatMD&, const MatM&, MatP&) const;
template void GradF<1>::jointKinematics(const MatDP&, std::size_t, Kinematics&) const;
template void GradF<2>::jointKinematics(const MatDP&, std::size_t, Kinematics&) const;
template void GradF<3>::jointKinematics(const MatDP&, std::size_t, Kinematics&) const;

} // namespace sph
