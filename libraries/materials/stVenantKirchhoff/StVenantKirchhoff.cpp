#include "materials/stVenantKirchhoff/StVenantKirchhoff.hpp"

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
    return Material<D>::commonSchema().include(IsotropicElasticity::schema());
}

template <int D>
StVenantKirchhoff<D>::StVenantKirchhoff(const Params& params, const typename Material<D>::Args&)
    : MaterialModel<D, StVenantKirchhoff<D>>(params),
      elastic_(IsotropicElasticity::read<D>(params)), minimumModulus_(elastic_.waveModulus<D>())
{
}

template class StVenantKirchhoff<1>;
template class StVenantKirchhoff<2>;
template class StVenantKirchhoff<3>;

SPH_REGISTER_DIM_MODEL(Material, StVenantKirchhoff, "stVenantKirchhoff");

} // namespace sph
