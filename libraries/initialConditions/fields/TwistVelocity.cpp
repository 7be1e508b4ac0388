// `twist` initial velocity field (3D; see Fields.hpp): a rotation about an axis whose angular
// velocity grows from zero at the base as a sine (the twisting column of Aguirre et al. 2014,
// Lee et al. 2016):
//   v = omega sin(pi s / (2 height)) a x (X - point),   s = a . (X - point),  a = axis / |axis|
// s is the distance along the axis from `point` (the base); v = 0 at s = 0 and the full
// rotation omega at s = height. Beyond [0, height] the same formula continues (the sine falls
// again above height, changes sign below the base).
#include "initialConditions/fields/Fields.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace sph
{

template <int D>
class TwistVelocity : public VelocityField<D>
{
public:
    static std::string description()
    {
        return "Twist about an axis: v = omega sin(pi s / (2 height)) axis x (X - point), s the "
               "distance from point along axis (the twisting column; zero at the base s = 0).";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::real("omega", "angular velocity at s = height [rad/s]"))
            .add(Key::vector("point", "the axis's point at the base, s = 0 [m]"))
            .add(Key::vector("axis", "the axis direction (normalised)").defaultValue("(0 0 1)"))
            .add(Key::real("height", "H: the angular velocity is omega sin(pi s / (2 H)) [m]").positive());
    }
    TwistVelocity(const Params& p, const typename VelocityField<D>::Args&)
        : point_(toVec<D>(p.vector("point"))), omega_(p.real("omega")),
          k_(std::numbers::pi / (2.0 * p.real("height")))
    {
        const Vec<D> axis = toVec<D>(p.vector("axis"));
        if (!(axis.norm() > 0.0))
        {
            p.fail("axis", "twist: 'axis' must not be the zero vector");
        }
        axis_ = axis.normalized();
    }
    Vec<D> velocity(const Vec<D>& X) const override
    {
        const Vec<D> r = X - point_;
        const double s = axis_.dot(r);
        return Vec<D>(omega_ * std::sin(k_ * s) * axis_.cross(r));
    }

private:
    Vec<D> point_;
    Vec<D> axis_;
    double omega_;
    double k_;
};

SPH_REGISTER_DIM_MODEL_FOR(VelocityField, TwistVelocity, "twist", 3);

} // namespace sph
