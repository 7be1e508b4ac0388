#pragma once
// Wendland C2 kernel, support 2h; spec §1:
//   1D: W = (5/(8h)) (1 - q/2)^3 (1.5 q + 1);   2D/3D: W = alpha_d (1 - q/2)^4 (2q + 1),
//   alpha_2 = 7/(4 pi h^2), alpha_3 = 21/(16 pi h^3).
// Keys: hOverDx (see Kernel.hpp; 1.5 to 2 is usual for this kernel).

#include "kernels/Kernel.hpp"

namespace sph
{

struct WendlandC2Shape
{
    static constexpr double support = 2.0;
    static double sigma(int dim);
    static double w(double q, int dim)
    {
        if (q >= 2.0)
        {
            return 0.0;
        }
        const double t = 1.0 - 0.5 * q;
        if (dim == 1)
        {
            return t * t * t * (1.5 * q + 1.0);
        }
        return t * t * t * t * (2.0 * q + 1.0);
    }
    static double dwdq(double q, int dim)
    {
        if (q >= 2.0)
        {
            return 0.0;
        }
        const double t = 1.0 - 0.5 * q;
        if (dim == 1)
        {
            return -3.0 * q * t * t;
        }
        return -5.0 * q * t * t * t;
    }
};

class WendlandC2 : public KernelModel<WendlandC2Shape>
{
public:
    static std::string description();
    static Schema schema() { return commonSchema(); }
    using KernelModel::KernelModel;
};

} // namespace sph
