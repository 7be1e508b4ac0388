#include "materials/j2Plasticity/J2Plasticity.hpp"

#include "core/Format.hpp"

namespace sph
{

template <int D>
std::string J2Plasticity<D>::description()
{
    return "Finite-strain von Mises plasticity, linear isotropic hardening: F = Fe Fp, Hencky "
           "elasticity, radial return on the log strain (without principal axes: in 3D by its "
           "series where the elastic strain is small, in 2D in closed form; key logarithm; "
           "docs/theory/plasticity.md §P12-§P13); "
           "2D plane strain, 1D uniaxial stress.";
}

template <int D>
Schema J2Plasticity<D>::schema()
{
    return Material<D>::commonSchema()
        .include(IsotropicElasticity::schema())
        .include(ReturnMapPlasticity<D, J2Plasticity<D>>::lawSchema())
        .add(Key::real("yieldStress", "initial yield stress sigmaY0 [Pa]").positive())
        .add(Key::real("hardeningModulus", "linear isotropic hardening modulus H = "
                                           "dsigmaY/dalpha [Pa]; > -3 mu (1D: > -E), < 0 "
                                           "softens")
                 .defaultValue("0"));
}

template <int D>
J2Plasticity<D>::J2Plasticity(const Params& params, const typename Material<D>::Args& args)
    : ReturnMapPlasticity<D, J2Plasticity<D>>(params, args), sigmaY0_(params.real("yieldStress")),
      H_(params.real("hardeningModulus"))
{
    // Δγ > 0 needs a positive denominator in the return (§P5, §P6).
    const double limit = D == 1 ? -this->elastic_.E : -3.0 * this->elastic_.mu;
    if (!(H_ > limit))
    {
        params.fail("hardeningModulus",
                    "j2Plasticity: hardeningModulus " + formatNumber(H_) + " is below the limit " +
                        formatNumber(limit) + (D == 1 ? " (-E)" : " (-3 mu)") +
                        ": the return map has no solution (softening faster than elastic "
                        "unloading)",
                    {"Use a value in (" + formatNumber(limit) + ", inf); 0 is perfectly plastic."});
    }
}

template <int D>
double J2Plasticity<D>::hardeningEnergy(double alpha) const
{
    if (H_ >= 0.0 || sigmaY0_ + H_ * alpha >= 0.0)
    {
        return 0.5 * H_ * alpha * alpha;
    }
    const double exhausted = -sigmaY0_ / H_; // σy reaches 0 here and stays 0
    return 0.5 * H_ * exhausted * exhausted - sigmaY0_ * (alpha - exhausted);
}

template <int D>
PlasticFlow J2Plasticity<D>::returnUniaxial(double& eps, double alpha) const
{
    // §P6: Φ = |τ| − σy(α) with τ = E ε; ε ← ε − Δγ sgn τ_tr.
    const double E = this->elastic_.E;
    const double tauTrial = E * eps;
    if (!(std::abs(tauTrial) > yieldStress(alpha)))
    {
        return {};
    }
    double deltaGamma = (std::abs(tauTrial) - sigmaY0_ - H_ * alpha) / (E + H_);
    if (sigmaY0_ + H_ * (alpha + deltaGamma) < 0.0)
    {
        deltaGamma = std::abs(tauTrial) / E;
    }
    eps -= std::copysign(deltaGamma, tauTrial);
    return flowOf(deltaGamma, alpha);
}

template class J2Plasticity<1>;
template class J2Plasticity<2>;
template class J2Plasticity<3>;

SPH_REGISTER_DIM_MODEL(Material, J2Plasticity, "j2Plasticity");

} // namespace sph
