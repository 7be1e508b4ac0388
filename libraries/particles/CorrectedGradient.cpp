#include "particles/CorrectedGradient.hpp"

namespace sph
{

template struct CorrectedGradient<1>;
template struct CorrectedGradient<2>;
template struct CorrectedGradient<3>;

} // namespace sph
