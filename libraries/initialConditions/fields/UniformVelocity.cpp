// `uniform` initial velocity field (the default type; see Fields.hpp).
//   velocity (vector)    v = velocity
#include "initialConditions/fields/Fields.hpp"

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

SPH_REGISTER_DIM_MODEL(VelocityField, UniformVelocity, "uniform");

} // namespace sph
