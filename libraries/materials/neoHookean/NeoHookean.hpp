#pragma once
// Nearly incompressible Neo-Hookean, the seed's eq. (36) (spec §8):
//   J = det F,  I1 = tr(F^T F) + (3 - d)   (plane strain / uniaxial strain: the missing
//   stretches are 1),
//   Ψ = ½ μ (J^{-2/3} I1 - 3) + ½ κ (J - 1)^2,
//   P = μ J^{-2/3} (F - (I1/3) F^{-T}) + κ J (J - 1) F^{-T}.
// Keys:
//   mu    | shear modulus μ [Pa]   | required
//   kappa | bulk modulus κ [Pa]    | required
//   rho   | initial density        | required
// Seed rings: μ = 0.3571 MPa, κ = 1.67 MPa (E = 1 MPa, ν = 0.4).
// Wave speed: the principal longitudinal modulus ∂²Ψ/∂λ_i² at the smallest stretch λ,
//   M = ½ μ J^{-2/3} ((10/9) I1/λ^2 - 2/3) + κ J^2/λ^2   (= κ + 4μ/3 at F = I).

#include "materials/Material.hpp"
#include "particles/FastMath.hpp"

namespace sph
{

template <int D>
class NeoHookean : public MaterialModel<D, NeoHookean<D>>
{
public:
    static std::string description();
    static Schema schema();
    NeoHookean(const Params& params, const typename Material<D>::Args& args);

    Mat<D> stressOf(const Mat<D>& F) const
    {
        const double J = F.determinant();
        const Mat<D> FinvT = F.inverse().transpose();
        const double I1 = F.squaredNorm() + (3 - D);
        const double c = inverseCubeRoot(J);
        const double Jm23 = c * c;
        return mu_ * Jm23 * (F - (I1 / 3.0) * FinvT) + kappa_ * J * (J - 1.0) * FinvT;
    }
    double energyOf(const Mat<D>& F) const
    {
        const double J = F.determinant();
        const double I1 = F.squaredNorm() + (3 - D);
        const double c = inverseCubeRoot(J);
        return 0.5 * mu_ * (c * c * I1 - 3.0) + 0.5 * kappa_ * (J - 1.0) * (J - 1.0);
    }
    double waveSpeedOf(const Mat<D>& F) const
    {
        const double J = F.determinant();
        const double I1 = F.squaredNorm() + (3 - D);
        const double lowest = stretchSquaredRange<D>(F).first;
        const double c = inverseCubeRoot(J);
        const double modulus = 0.5 * mu_ * c * c * ((10.0 / 9.0) * I1 / lowest - 2.0 / 3.0) +
                               kappa_ * J * J / lowest;
        return std::sqrt(std::max(modulus, 0.0) / this->density());
    }
    double youngsModulus() const override { return 9.0 * kappa_ * mu_ / (3.0 * kappa_ + mu_); }
    std::string summary() const override;

private:
    double mu_;
    double kappa_;
};

} // namespace sph
