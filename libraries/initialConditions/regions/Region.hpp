#pragma once
// Regions select particles of a body by their INITIAL positions X; constraints and initial
// velocities in constant/bodies name one:
//
//   region { type box; min (0 0); max (0.01 0.02); }
//
// Types: all, box, sphere, halfSpace, nearest (the one particle closest to a point); each in its
// own file: AllRegion.cpp, BoxRegion.cpp, SphereRegion.cpp, HalfSpaceRegion.cpp, NearestRegion.cpp.

#include "core/Registry.hpp"
#include "particles/Types.hpp"

#include <vector>

namespace sph
{

template <int D>
class Region
{
public:
    static constexpr const char* family = "region";
    static constexpr int dimension = D;
    struct Args
    {
    };

    virtual ~Region() = default;

    // Indices (into X) of the selected particles among [begin, end).
    virtual std::vector<std::size_t> select(const std::vector<Vec<D>>& X, std::size_t begin,
                                            std::size_t end) const
    {
        std::vector<std::size_t> chosen;
        for (std::size_t i = begin; i < end; ++i)
        {
            if (contains(X[i]))
            {
                chosen.push_back(i);
            }
        }
        return chosen;
    }

protected:
    virtual bool contains(const Vec<D>& point) const = 0;
};

} // namespace sph
