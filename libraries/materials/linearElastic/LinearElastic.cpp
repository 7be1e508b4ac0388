#include "materials/linearElastic/LinearElastic.hpp"

#include <sstream>

namespace sph
{

template <int D>
std::string LinearElastic<D>::description()
{
    return "Linear elasticity: 1D bar P = E(F-1) (the Dyka bar); 2D plane strain / 3D small "
           "strain, not objective (spec §8).";
}

template <int D>
Schema LinearElastic<D>::schema()
{
    return Material<D>::commonSchema()
        .add(Key::real("E", "Young's modulus [Pa]").positive())
        .add(Key::real("nu", "Poisson's ratio (2D plane strain and 3D; unused in 1D)")
                 .range(-1.0, 0.5, false, false)
                 .optional());
}

template <int D>
LinearElastic<D>::LinearElastic(const Params& params, const typename Material<D>::Args&)
    : MaterialModel<D, LinearElastic<D>>(params), E_(params.real("E"))
{
    if constexpr (D == 1)
    {
        waveSpeed_ = std::sqrt(E_ / this->density());
    }
    else
    {
        if (!params.has("nu"))
        {
            params.fail("E", "linearElastic in " + std::to_string(D) + "D needs 'nu'",
                        {"Add e.g. 'nu 0.3;' (Poisson's ratio, in (-1, 0.5))."});
        }
        nu_ = params.real("nu");
        std::tie(lambda_, mu_) = lameFromYoung(E_, nu_);
        waveSpeed_ = std::sqrt((lambda_ + 2.0 * mu_) / this->density());
    }
}

template <int D>
std::string LinearElastic<D>::summary() const
{
    std::ostringstream out;
    out << "linearElastic(E=" << E_;
    if (D > 1)
    {
        out << ", nu=" << nu_;
    }
    out << ", rho=" << this->density() << ", c=" << waveSpeed_ << " m/s)";
    return out.str();
}

template class LinearElastic<1>;
template class LinearElastic<2>;
template class LinearElastic<3>;

SPH_REGISTER_DIM_MODEL(Material, LinearElastic, "linearElastic");

} // namespace sph
