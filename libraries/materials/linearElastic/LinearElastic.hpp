#pragma once
// Linear elasticity (spec §8).
//   1D (bar):  Ψ = ½ E (F - 1)^2,  P = E (F - 1): with total-Lagrangian CSPH this is exactly the
//              linear wave equation of the Dyka bar (the seed's κ is E here).
//   2D/3D:     small strain ε = ½(F + F^T) - I, σ = λ tr ε I + 2 μ ε, P := σ,
//              Ψ = ½ λ (tr ε)^2 + μ ε:ε. Not objective: for small rotations and tests only.
// Keys:
//   E   | Young's modulus [Pa]                              | required
//   nu  | Poisson's ratio (2D plane strain and 3D; unused 1D) | required in 2D/3D
//   rho | initial density                                    | required
// Wave speed: sqrt(E/ρ0) in 1D, sqrt((λ + 2μ)/ρ0) in 2D/3D (constant tangent).

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
            return Mat<D>::Constant(E_ * (F(0, 0) - 1.0));
        }
        else
        {
            const Mat<D> eps = 0.5 * (F + F.transpose()) - Mat<D>::Identity();
            return lambda_ * eps.trace() * Mat<D>::Identity() + 2.0 * mu_ * eps;
        }
    }
    double energyOf(const Mat<D>& F) const
    {
        if constexpr (D == 1)
        {
            const double s = F(0, 0) - 1.0;
            return 0.5 * E_ * s * s;
        }
        else
        {
            const Mat<D> eps = 0.5 * (F + F.transpose()) - Mat<D>::Identity();
            const double tr = eps.trace();
            return 0.5 * lambda_ * tr * tr + mu_ * eps.squaredNorm();
        }
    }
    double waveSpeedOf(const Mat<D>&) const { return waveSpeed_; }
    double youngsModulus() const override { return E_; }
    std::string summary() const override;

private:
    double E_;
    double nu_ = 0.0;
    double lambda_ = 0.0;
    double mu_ = 0.0;
    double waveSpeed_;
};

} // namespace sph
