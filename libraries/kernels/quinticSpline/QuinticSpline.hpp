#pragma once
// Quintic spline kernel (Morris 1996), support 3h; spec §1:
//   w(q) = (3 - q)^5_+ - 6 (2 - q)^5_+ + 15 (1 - q)^5_+,
//   sigma_1 = 1/120, sigma_2 = 7/(478 pi), sigma_3 = 1/(120 pi).
// Keys: hOverDx (see Kernel.hpp). Wider support: about 2.3 times the neighbours of the cubic
// spline in 2D at the same h.

#include "kernels/Kernel.hpp"

namespace sph
{

struct QuinticSplineShape
{
    static constexpr double support = 3.0;
    static double sigma(int dim);
    static double w(double q, int)
    {
        const auto p5 = [](double t) { return t > 0.0 ? t * t * t * t * t : 0.0; };
        return p5(3.0 - q) - 6.0 * p5(2.0 - q) + 15.0 * p5(1.0 - q);
    }
    static double dwdq(double q, int)
    {
        const auto p4 = [](double t) { return t > 0.0 ? t * t * t * t : 0.0; };
        return -5.0 * p4(3.0 - q) + 30.0 * p4(2.0 - q) - 75.0 * p4(1.0 - q);
    }
};

class QuinticSpline : public KernelModel<QuinticSplineShape>
{
public:
    static std::string description();
    static Schema schema() { return commonSchema(); }
    using KernelModel::KernelModel;
};

} // namespace sph
