#pragma once
// Cubic B-spline kernel (Monaghan 1992), support 2h; spec §1:
//   w(q) = 1 - 1.5 q^2 + 0.75 q^3 (q < 1),  0.25 (2 - q)^3 (1 <= q < 2),  0 beyond;
//   sigma_1 = 2/3, sigma_2 = 10/(7 pi), sigma_3 = 1/pi.
// Keys: hOverDx (see Kernel.hpp). The seed paper's kernel.

#include "kernels/Kernel.hpp"

namespace sph
{

struct CubicSplineShape
{
    static constexpr double support = 2.0;
    static double sigma(int dim);
    static double w(double q, int)
    {
        if (q < 1.0)
        {
            return 1.0 - 1.5 * q * q + 0.75 * q * q * q;
        }
        if (q < 2.0)
        {
            const double t = 2.0 - q;
            return 0.25 * t * t * t;
        }
        return 0.0;
    }
    static double dwdq(double q, int)
    {
        if (q < 1.0)
        {
            return -3.0 * q + 2.25 * q * q;
        }
        if (q < 2.0)
        {
            const double t = 2.0 - q;
            return -0.75 * t * t;
        }
        return 0.0;
    }
};

class CubicSpline : public KernelModel<CubicSplineShape>
{
public:
    static std::string description();
    static Schema schema() { return commonSchema(); }
    using KernelModel::KernelModel;
};

} // namespace sph
