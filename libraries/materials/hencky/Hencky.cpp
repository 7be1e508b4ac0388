#include "materials/hencky/Hencky.hpp"

namespace sph
{

template <int D>
std::string Hencky<D>::description()
{
    return "Hencky (logarithmic strain) elasticity: psi = mu |dev ln V|^2 + K/2 (tr ln V)^2, "
           "tau = 2 mu dev ln V + K tr ln V I (docs/theory/plasticity.md §P2); the elastic law "
           "of j2Plasticity.";
}

template <int D>
Schema Hencky<D>::schema()
{
    return Material<D>::commonSchema().include(IsotropicElasticity::schema());
}

template <int D>
Hencky<D>::Hencky(const Params& params, const typename Material<D>::Args&)
    : MaterialModel<D, Hencky<D>>(params), elastic_(IsotropicElasticity::read<D>(params)),
      law_(elastic_)
{
}

template class Hencky<1>;
template class Hencky<2>;
template class Hencky<3>;

SPH_REGISTER_DIM_MODEL(Material, Hencky, "hencky");

} // namespace sph
