#include "kernels/wendlandC2/WendlandC2.hpp"

#include <numbers>

namespace sph
{

double WendlandC2Shape::sigma(int dim)
{
    switch (dim)
    {
    case 1:
        return 5.0 / 8.0;
    case 2:
        return 7.0 / (4.0 * std::numbers::pi);
    default:
        return 21.0 / (16.0 * std::numbers::pi);
    }
}

std::string WendlandC2::description()
{
    return "Wendland C2, support 2h; positive Fourier transform (no pairing instability) "
           "(spec §1).";
}

SPH_REGISTER_MODEL(Kernel, WendlandC2, "wendlandC2");

} // namespace sph
