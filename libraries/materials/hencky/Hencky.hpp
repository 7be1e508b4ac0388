#pragma once
// `hencky`: logarithmic-strain elasticity (docs/theory/plasticity.md §P2), the elastic law of
// the plastic materials (`j2Plasticity` without yielding is exactly this):
//   εᵢ = ln λᵢ (principal stretches of F),  Ψ = μ |dev ε|² + ½ K (tr ε)²,
//   τ = 2μ dev ε + K tr ε 1,  P = τ F⁻ᵀ;
// 2D plane strain (ε_zz = 0), 1D a bar in uniaxial stress: Ψ = ½ E (ln λ)², P = E ln λ / λ.
// Keys: E, nu (IsotropicElasticity.hpp), rho (Material.hpp).
// Wave speed: the principal longitudinal modulus ∂P_ii/∂F_ii = (M − τᵢ)/λᵢ² (M = K + 4μ/3; 1D: E).

#include "materials/LogarithmicElasticity.hpp"
#include "materials/Material.hpp"

namespace sph
{

template <int D>
class Hencky : public MaterialModel<D, Hencky<D>>
{
public:
    static std::string description();
    static Schema schema();
    Hencky(const Params& params, const typename Material<D>::Args& args);

    Mat<D> stressOf(const Mat<D>& F) const
    {
        if constexpr (D == 1)
        {
            return Mat<D>::Constant(elastic_.E * std::log(F(0, 0)) / F(0, 0));
        }
        else
        {
            const PrincipalStrain<D> p = principalStrain<D>(F * F.transpose());
            return p.assemble(law_.kirchhoff(p.eps)) * F.inverse().transpose();
        }
    }
    double energyOf(const Mat<D>& F) const
    {
        if constexpr (D == 1)
        {
            const double eps = std::log(F(0, 0));
            return 0.5 * elastic_.E * eps * eps;
        }
        else
        {
            return law_.energy(principalStrain<D>(F * F.transpose()).eps);
        }
    }
    double waveSpeedOf(const Mat<D>& F) const
    {
        double modulus;
        if constexpr (D == 1)
        {
            const double lambda = F(0, 0);
            modulus = elastic_.E * (1.0 - std::log(lambda)) / (lambda * lambda);
        }
        else
        {
            const PrincipalStrain<D> p = principalStrain<D>(F * F.transpose());
            modulus = elasticLongitudinalModulus<D>(law_, p, law_.kirchhoff(p.eps));
        }
        return std::sqrt(std::max(modulus, 0.0) / this->density());
    }
    double youngsModulus() const override { return elastic_.E; }

private:
    IsotropicElasticity elastic_;
    HenckyLaw law_;
};

} // namespace sph
