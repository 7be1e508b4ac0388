#pragma once
// Linear elasticity (spec §8).
//   1D (bar):  Ψ = ½ E (F - 1)^2,  P = E (F - 1): with total-Lagrangian CSPH this is exactly the
//              linear wave equation of the Dyka bar (the seed's κ is E here).
//   2D/3D:     small strain ε = ½(F + F^T) - I, σ = λ tr ε I + 2 μ ε, P := σ,
//              Ψ = ½ λ (tr ε)^2 + μ ε:ε. Not objective: for small rotations and tests only.
// Keys: E, nu (IsotropicElasticity.hpp: λ, μ from E, ν), rho (Material.hpp).
// Wave speed: sqrt(E/ρ0) in 1D, sqrt((λ + 2μ)/ρ0) in 2D/3D (constant tangent).

#include "materials/IsotropicElasticity.hpp"
#include "materials/Material.hpp"

namespace sph
{

template <int D>
class LinearElastic : public MaterialModel<D, LinearElastic<D>>
{
public:
    static std::string description();
    static Schema schema();
    LinearElastic(const Params& params, const typename Material<D>::Args& args);

    Mat<D> stressOf(const Mat<D>& F) const
    {
        if constexpr (D == 1)
        {
            return Mat<D>::Constant(elastic_.E * (F(0, 0) - 1.0));
        }
        else
        {
            const Mat<D> eps = 0.5 * (F + F.transpose()) - Mat<D>::Identity();
            return elastic_.lambda * eps.trace() * Mat<D>::Identity() + 2.0 * elastic_.mu * eps;
        }
    }
    double energyOf(const Mat<D>& F) const
    {
        if constexpr (D == 1)
        {
            const double s = F(0, 0) - 1.0;
            return 0.5 * elastic_.E * s * s;
        }
        else
        {
            const Mat<D> eps = 0.5 * (F + F.transpose()) - Mat<D>::Identity();
            const double tr = eps.trace();
            return 0.5 * elastic_.lambda * tr * tr + elastic_.mu * eps.squaredNorm();
        }
    }
    double waveSpeedOf(const Mat<D>&) const { return waveSpeed_; }
    double youngsModulus() const override { return elastic_.E; }

private:
    IsotropicElasticity elastic_;
    double waveSpeed_;
};

} // namespace sph
