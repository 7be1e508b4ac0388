// `cantileverMode` initial velocity field (2D and 3D; see Fields.hpp): the first bending mode of
// a clamped plate along x (Gray et al. 2001; spec §11.3):
//   v_y = amplitude [M(cos kξ - cosh kξ) - N(sin kξ - sinh kξ)]/Q,
//   ξ = X_x - clamp, k = kL/length, M = sin kL + sinh kL, N = cos kL + cosh kL,
//   Q = 2 (cos kL sinh kL - sin kL cosh kL); 0 inside the clamp (ξ < 0).
#include "initialConditions/fields/Fields.hpp"

#include <cmath>

namespace sph
{

template <int D>
class CantileverMode : public VelocityField<D>
{
public:
    static std::string description()
    {
        return "First bending mode of a plate clamped at x = clamp (Gray et al. 2001, spec §11.3): "
               "transverse velocity along y.";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::real("clamp", "x of the clamped end of the free part [m]"))
            .add(Key::real("length", "free length L [m]").positive())
            .add(Key::real("amplitude", "velocity scale V_f c0 [m/s]"))
            .add(Key::real("kL", "k L of the mode (1.875: the first)").positive().defaultValue("1.875"));
    }
    CantileverMode(const Params& p, const typename VelocityField<D>::Args&)
        : clamp_(p.real("clamp")), k_(p.real("kL") / p.real("length")), amplitude_(p.real("amplitude"))
    {
        const double kL = p.real("kL");
        M_ = std::sin(kL) + std::sinh(kL);
        N_ = std::cos(kL) + std::cosh(kL);
        Q_ = 2.0 * (std::cos(kL) * std::sinh(kL) - std::sin(kL) * std::cosh(kL));
    }
    Vec<D> velocity(const Vec<D>& X) const override
    {
        Vec<D> v = Vec<D>::Zero();
        const double xi = X[0] - clamp_;
        if (xi > 0.0)
        {
            const double kx = k_ * xi;
            v[1] = amplitude_ * (M_ * (std::cos(kx) - std::cosh(kx)) - N_ * (std::sin(kx) - std::sinh(kx))) / Q_;
        }
        return v;
    }

private:
    double clamp_;
    double k_;
    double amplitude_;
    double M_ = 0.0;
    double N_ = 0.0;
    double Q_ = 0.0;
};

SPH_REGISTER_DIM_MODEL_FOR(VelocityField, CantileverMode, "cantileverMode", 2, 3);

} // namespace sph
