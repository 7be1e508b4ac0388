#include "materials/stVenantKirchhoff/StVenantKirchhoff.hpp"

#include <sstream>

namespace sph
{

template <int D>
std::string StVenantKirchhoff<D>::description()
{
    return "Saint Venant-Kirchhoff: P = F S, S = lambda tr(E) I + 2 mu E (spec §8); 1D "
           "uniaxial, 2D plane strain.";
}

template <int D>
Schema StVenantKirchhoff<D>::schema()
{
    return Material<D>::commonSchema()
        .add(Key::real("E", "Young's modulus [Pa]").positive())
        .add(Key::real("nu", "Poisson's ratio (2D plane strain and 3D; unused in 1D)")
                 .range(-1.0, 0.5, false, false)
                 .optional());
}

template <int D>
StVenantKirchhoff<D>::StVenantKirchhoff(const Params& params, const typename Material<D>::Args&)
    : MaterialModel<D, StVenantKirchhoff<D>>(params), young_(params.real("E"))
{
    if constexpr (D == 1)
    {
        minimumModulus_ = young_;
    }
    else
    {
        if (!params.has("nu"))
        {
            params.fail("E", "stVenantKirchhoff in " + std::to_string(D) + "D needs 'nu'",
                        {"Add e.g. 'nu 0.3;' (Poisson's ratio, in (-1, 0.5))."});
        }
        nu_ = params.real("nu");
        std::tie(lambda_, mu_) = lameFromYoung(young_, nu_);
        minimumModulus_ = lambda_ + 2.0 * mu_;
    }
}

template <int D>
std::string StVenantKirchhoff<D>::summary() const
{
    std::ostringstream out;
    out << "stVenantKirchhoff(E=" << young_;
    if (D > 1)
    {
        out << ", nu=" << nu_;
    }
    out << ", rho=" << this->density() << ")";
    return out.str();
}

template class StVenantKirchhoff<1>;
template class StVenantKirchhoff<2>;
template class StVenantKirchhoff<3>;

SPH_REGISTER_DIM_MODEL(Material, StVenantKirchhoff, "stVenantKirchhoff");

} // namespace sph
