// `all` region: every particle of the body (see Region.hpp).
#include "initialConditions/regions/Region.hpp"

namespace sph
{

template <int D>
class AllRegion : public Region<D>
{
public:
    static std::string description() { return "Every particle of the body."; }
    static Schema schema() { return Schema(); }
    AllRegion(const Params&, const typename Region<D>::Args&) {}

protected:
    bool contains(const Vec<D>&) const override { return true; }
};

SPH_REGISTER_DIM_MODEL(Region, AllRegion, "all");

} // namespace sph
