// `nearest` region: the single particle whose X is closest to `point` (lowest index on ties;
// see Region.hpp).
#include "initialConditions/regions/Region.hpp"

#include <limits>

namespace sph
{

template <int D>
class NearestRegion : public Region<D>
{
public:
    static std::string description()
    {
        return "The one particle of the body closest to 'point' (e.g. a bar's end).";
    }
    static Schema schema() { return Schema().add(Key::vector("point", "target point [m]")); }
    NearestRegion(const Params& p, const typename Region<D>::Args&)
        : point_(toVec<D>(p.vector("point")))
    {
    }
    std::vector<std::size_t> select(const std::vector<Vec<D>>& X, std::size_t begin,
                                    std::size_t end) const override
    {
        std::size_t best = begin;
        double bestDistance = std::numeric_limits<double>::max();
        for (std::size_t i = begin; i < end; ++i)
        {
            const double distance = (X[i] - point_).squaredNorm();
            if (distance < bestDistance)
            {
                best = i;
                bestDistance = distance;
            }
        }
        return begin < end ? std::vector<std::size_t>{best} : std::vector<std::size_t>{};
    }

protected:
    bool contains(const Vec<D>&) const override { return false; }

private:
    Vec<D> point_;
};

SPH_REGISTER_DIM_MODEL(Region, NearestRegion, "nearest");

} // namespace sph
