// Initial velocity fields (see Fields.hpp). Each is a few lines; registered here, one line each.
//   uniform        velocity (vector)                                        v = velocity
//   rotation       omega [rad/s], centre, axis (3 components, (0 0 1) in 2D)  v = ω axis × (X - centre)
//   cantileverMode the first bending mode of a clamped plate along x (Gray et al. 2001; spec
//                  §11.3): v_y = amplitude [M(cos kξ - cosh kξ) - N(sin kξ - sinh kξ)]/Q,
//                  ξ = X_x - clamp, k = kL/length, M = sin kL + sinh kL, N = cos kL + cosh kL,
//                  Q = 2 (cos kL sinh kL - sin kL cosh kL); 0 inside the clamp (ξ < 0).
#include "particles/fields/Fields.hpp"

#include <Eigen/Geometry>

#include <cmath>

namespace sph
{

template <int D>
class UniformVelocity : public VelocityField<D>
{
public:
    static std::string description() { return "The same velocity everywhere in the region."; }
    static Schema schema() { return Schema().add(Key::vector("velocity", "the velocity [m/s]")); }
    UniformVelocity(const Params& p, const typename VelocityField<D>::Args&)
        : velocity_(toVec<D>(p.vector("velocity")))
    {
    }
    Vec<D> velocity(const Vec<D>&) const override { return velocity_; }

private:
    Vec<D> velocity_;
};

template <int D>
class RotationVelocity : public VelocityField<D>
{
public:
    static std::string description()
    {
        return "Rigid rotation v = omega axis x (X - centre) (axis (0 0 1) in 2D).";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::real("omega", "angular velocity [rad/s]"))
            .add(Key::vector("centre", "a point on the axis [m]"))
            .add(Key::vector("axis", "the rotation axis (3 components; (0 0 1) in 2D)").size(3).defaultValue("(0 0 1)"));
    }
    RotationVelocity(const Params& p, const typename VelocityField<D>::Args&)
        : centre_(toVec<D>(p.vector("centre")))
    {
        const auto& axis = p.vector("axis");
        omega_ = p.real("omega") * Eigen::Vector3d(axis[0], axis[1], axis[2]).normalized();
        if (D == 2 && (axis[0] != 0.0 || axis[1] != 0.0))
        {
            p.fail("axis", "rotation: in 2D the axis is (0 0 1)");
        }
    }
    Vec<D> velocity(const Vec<D>& X) const override
    {
        return omega_.cross(embed<D>(Vec<D>(X - centre_))).template head<D>();
    }

private:
    Vec<D> centre_;
    Eigen::Vector3d omega_;
};

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

SPH_REGISTER_DIM_MODEL(VelocityField, UniformVelocity, "uniform");
SPH_REGISTER_DIM_MODEL_FOR(VelocityField, RotationVelocity, "rotation", 2, 3);
SPH_REGISTER_DIM_MODEL_FOR(VelocityField, CantileverMode, "cantileverMode", 2, 3);

} // namespace sph
