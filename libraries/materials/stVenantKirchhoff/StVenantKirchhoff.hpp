#pragma once
// Saint Venant-Kirchhoff (spec §8): E = ½(F^T F - I), S = λ tr E I + 2 μ E, P = F S,
// Ψ = ½ λ (tr E)^2 + μ E:E. 1D: uniaxial, S = E_Young · E, P = E_Young F (F^2 - 1)/2.
// Objective, but softens without bound in strong compression.
// Keys: E, nu (IsotropicElasticity.hpp: Lamé λ_L, μ from E, ν), rho (Material.hpp).
// Wave speed: the largest principal longitudinal modulus, at the largest stretch λ:
//   M = λ_L tr E + μ (λ^2 - 1) + λ^2 (λ_L + 2μ)  (1D: E (3F^2 - 1)/2).

#include "materials/IsotropicElasticity.hpp"
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
            return F * (elastic_.E * E);
        }
        else
        {
            return F * (elastic_.lambda * E.trace() * Mat<D>::Identity() + 2.0 * elastic_.mu * E);
        }
    }
    double energyOf(const Mat<D>& F) const
    {
        const Mat<D> E = 0.5 * (F.transpose() * F - Mat<D>::Identity());
        if constexpr (D == 1)
        {
            return 0.5 * elastic_.E * E(0, 0) * E(0, 0);
        }
        else
        {
            const double tr = E.trace();
            return 0.5 * elastic_.lambda * tr * tr + elastic_.mu * E.squaredNorm();
        }
    }
    double waveSpeedOf(const Mat<D>& F) const
    {
        const auto [lowest, highest] = stretchSquaredRange<D>(F);
        (void)lowest;
        double modulus = 0.0;
        if constexpr (D == 1)
        {
            modulus = elastic_.E * (3.0 * highest - 1.0) / 2.0;
        }
        else
        {
            const double trE = 0.5 * ((F.transpose() * F).trace() - D);
            modulus = elastic_.lambda * trE + elastic_.mu * (highest - 1.0) +
                      highest * (elastic_.lambda + 2.0 * elastic_.mu);
        }
        return std::sqrt(std::max(modulus, minimumModulus_) / this->density());
    }
    double youngsModulus() const override { return elastic_.E; }

private:
    IsotropicElasticity elastic_;
    double minimumModulus_; // the small-strain modulus: Δt never grows beyond the initial one
};

} // namespace sph
