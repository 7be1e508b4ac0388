#include "materials/linearElastic/LinearElastic.hpp"

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
    return Material<D>::commonSchema().include(IsotropicElasticity::schema());
}

template <int D>
LinearElastic<D>::LinearElastic(const Params& params, const typename Material<D>::Args&)
    : MaterialModel<D, LinearElastic<D>>(params), elastic_(IsotropicElasticity::read<D>(params)),
      waveSpeed_(std::sqrt(elastic_.waveModulus<D>() / this->density()))
{
}

template class LinearElastic<1>;
template class LinearElastic<2>;
template class LinearElastic<3>;

SPH_REGISTER_DIM_MODEL(Material, LinearElastic, "linearElastic");

} // namespace sph
