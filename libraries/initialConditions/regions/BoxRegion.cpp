// `box` region: min <= X <= max componentwise (see Region.hpp).
#include "initialConditions/regions/Region.hpp"

namespace sph
{

template <int D>
class BoxRegion : public Region<D>
{
public:
    static std::string description() { return "Axis-aligned box: min <= X <= max."; }
    static Schema schema()
    {
        return Schema()
            .add(Key::vector("min", "lower corner [m]"))
            .add(Key::vector("max", "upper corner [m]"));
    }
    BoxRegion(const Params& p, const typename Region<D>::Args&)
        : min_(toVec<D>(p.vector("min"))), max_(toVec<D>(p.vector("max")))
    {
        if ((max_.array() < min_.array()).any())
        {
            p.fail("max", "box: 'max' must not be below 'min' in any component");
        }
    }

protected:
    bool contains(const Vec<D>& point) const override
    {
        return (point.array() >= min_.array()).all() && (point.array() <= max_.array()).all();
    }

private:
    Vec<D> min_;
    Vec<D> max_;
};

SPH_REGISTER_DIM_MODEL(Region, BoxRegion, "box");

} // namespace sph
