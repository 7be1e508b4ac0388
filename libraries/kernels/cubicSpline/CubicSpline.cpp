#include "kernels/cubicSpline/CubicSpline.hpp"

#include <numbers>

namespace sph
{

double CubicSplineShape::sigma(int dim)
{
    switch (dim)
    {
    case 1:
        return 2.0 / 3.0;
    case 2:
        return 10.0 / (7.0 * std::numbers::pi);
    default:
        return 1.0 / std::numbers::pi;
    }
}

std::string CubicSpline::description()
{
    return "Cubic B-spline (Monaghan 1992), support 2h; the seed paper's kernel (spec §1).";
}

SPH_REGISTER_MODEL(Kernel, CubicSpline, "cubicSpline");

} // namespace sph
