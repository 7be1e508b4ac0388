#include "kernels/quinticSpline/QuinticSpline.hpp"

#include <numbers>

namespace sph
{

double QuinticSplineShape::sigma(int dim)
{
    switch (dim)
    {
    case 1:
        return 1.0 / 120.0;
    case 2:
        return 7.0 / (478.0 * std::numbers::pi);
    default:
        return 1.0 / (120.0 * std::numbers::pi);
    }
}

std::string QuinticSpline::description()
{
    return "Quintic spline (Morris 1996), support 3h (spec §1).";
}

SPH_REGISTER_MODEL(Kernel, QuinticSpline, "quinticSpline");

} // namespace sph
