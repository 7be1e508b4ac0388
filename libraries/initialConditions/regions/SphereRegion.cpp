// `sphere` region: |X - centre| <= radius (an interval in 1D, a disk in 2D; see Region.hpp).
#include "initialConditions/regions/Region.hpp"

namespace sph
{

template <int D>
class SphereRegion : public Region<D>
{
public:
    static std::string description() { return "Ball |X - centre| <= radius."; }
    static Schema schema()
    {
        return Schema()
            .add(Key::vector("centre", "centre [m]"))
            .add(Key::real("radius", "radius [m]").positive());
    }
    SphereRegion(const Params& p, const typename Region<D>::Args&)
        : centre_(toVec<D>(p.vector("centre"))), radius_(p.real("radius"))
    {
    }

protected:
    bool contains(const Vec<D>& point) const override
    {
        return (point - centre_).norm() <= radius_;
    }

private:
    Vec<D> centre_;
    double radius_;
};

SPH_REGISTER_DIM_MODEL(Region, SphereRegion, "sphere");

} // namespace sph
