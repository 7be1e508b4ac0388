#pragma once
// Saint Venant-Kirchhoff (spec §8): E = ½(F^T F - I), S = λ tr E I + 2 μ E, P = F S,
// Ψ = ½ λ (tr E)^2 + μ E:E. 1D: uniaxial, S = E_Young · E, P = E_Young F (F^2 - 1)/2.
// Objective, but softens without bound in strong compression.
// Keys:
//   E   | Young's modulus [Pa]                                | required
//   nu  | Poisson's ratio (2D plane strain and 3D; unused 1D)  | required in 2D/3D
//   rho | initial density                                      | required
// Wave speed: the largest principal longitudinal modulus, at the largest stretch λ:
//   M = λ_L tr E + μ (λ^2 - 1) + λ^2 (λ_L + 2μ)  (1D: E (3F^2 - 1)/2).

#include "materials/Material.hpp"

namespace sph
{

template <int D>
class StVenantKirchhoff : public MaterialModel<D, StVenantKirchhoff<D>>
{
public:
    static std::string description();
    static Schema schema();
    StVenantKirchhoff(const Params& params, const typename Material<D>::Args& args);

    Mat<D> stressOf(const Mat<D>& F) const
    {
        const Mat<D> E = 0.5 * (F.transpose() * F - Mat<D>::Identity());
        if constexpr (D == 1)
        {
            return F * (young_ * E);
        }
        else
        {
            return F * (lambda_ * E.trace() * Mat<D>::Identity() + 2.0 * mu_ * E);
        }
    }
    double energyOf(const Mat<D>& F) const
    {
        const Mat<D> E = 0.5 * (F.transpose() * F - Mat<D>::Identity());
        if constexpr (D == 1)
        {
            return 0.5 * young_ * E(0, 0) * E(0, 0);
        }
        else
        {
            const double tr = E.trace();
            return 0.5 * lambda_ * tr * tr + mu_ * E.squaredNorm();
        }
    }
    double waveSpeedOf(const Mat<D>& F) const
    {
        const auto [lowest, highest] = stretchSquaredRange<D>(F);
        (void)lowest;
        double modulus = 0.0;
        if constexpr (D == 1)
        {
            modulus = young_ * (3.0 * highest - 1.0) / 2.0;
        }
        else
        {
            const double trE = 0.5 * ((F.transpose() * F).trace() - D);
            modulus = lambda_ * trE + mu_ * (highest - 1.0) + highest * (lambda_ + 2.0 * mu_);
        }
        return std::sqrt(std::max(modulus, minimumModulus_) / this->density());
    }
    double youngsModulus() const override { return young_; }
    std::string summary() const override;

private:
    double young_;
    double nu_ = 0.0;
    double lambda_ = 0.0;
    double mu_ = 0.0;
    double minimumModulus_; // the small-strain modulus: Δt never grows beyond the initial one
};

} // namespace sph
