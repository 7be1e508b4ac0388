// `halfSpace` region: (X - point)·normal >= 0 (see Region.hpp).
#include "initialConditions/regions/Region.hpp"

namespace sph
{

template <int D>
class HalfSpaceRegion : public Region<D>
{
public:
    static std::string description() { return "Half space (X - point).normal >= 0."; }
    static Schema schema()
    {
        return Schema()
            .add(Key::vector("point", "a point on the boundary plane [m]"))
            .add(Key::vector("normal", "direction into the region"));
    }
    HalfSpaceRegion(const Params& p, const typename Region<D>::Args&)
        : point_(toVec<D>(p.vector("point"))), normal_(toVec<D>(p.vector("normal")))
    {
        if (normal_.norm() == 0.0)
        {
            p.fail("normal", "halfSpace: 'normal' must not be the zero vector");
        }
    }

protected:
    bool contains(const Vec<D>& X) const override { return (X - point_).dot(normal_) >= 0.0; }

private:
    Vec<D> point_;
    Vec<D> normal_;
};

SPH_REGISTER_DIM_MODEL(Region, HalfSpaceRegion, "halfSpace");

} // namespace sph
