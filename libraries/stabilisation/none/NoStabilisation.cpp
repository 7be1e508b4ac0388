#include "stabilisation/none/NoStabilisation.hpp"

namespace sph
{

template <int D>
std::string NoStabilisation<D>::description()
{
    return "Plain corrected SPH without stabilisation (spec §3, §4): the baseline that fails "
           "in updated-Lagrangian form.";
}

template class NoStabilisation<1>;
template class NoStabilisation<2>;
template class NoStabilisation<3>;

SPH_REGISTER_DIM_MODEL(Stabilisation, NoStabilisation, "none");

} // namespace sph
