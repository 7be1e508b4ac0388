#include "materials/neoHookean/NeoHookean.hpp"

namespace sph
{

template <int D>
std::string NeoHookean<D>::description()
{
    return "Nearly incompressible Neo-Hookean, seed eq. (36): psi = mu/2 (J^-2/3 I1 - 3) + "
           "kappa/2 (J-1)^2 (spec §8).";
}

template <int D>
Schema NeoHookean<D>::schema()
{
    return Material<D>::commonSchema()
        .add(Key::real("mu", "shear modulus [Pa]").positive())
        .add(Key::real("kappa", "bulk modulus [Pa]").positive());
}

template <int D>
NeoHookean<D>::NeoHookean(const Params& params, const typename Material<D>::Args&)
    : MaterialModel<D, NeoHookean<D>>(params), mu_(params.real("mu")), kappa_(params.real("kappa"))
{
}

template class NeoHookean<1>;
template class NeoHookean<2>;
template class NeoHookean<3>;

SPH_REGISTER_DIM_MODEL(Material, NeoHookean, "neoHookean");

} // namespace sph
