// `rotation` initial velocity field (2D and 3D; see Fields.hpp).
//   omega [rad/s], centre, axis (3 components, (0 0 1) in 2D)    v = ω axis × (X - centre)
#include "initialConditions/fields/Fields.hpp"

#include <Eigen/Geometry>

namespace sph
{

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

SPH_REGISTER_DIM_MODEL_FOR(VelocityField, RotationVelocity, "rotation", 2, 3);

} // namespace sph
