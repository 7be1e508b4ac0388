#pragma once
// Neighbour lists at positions that move a little between calls (same body, self first,
// increasing index: particles/NeighbourList.hpp), kept Verlet-style: a search with a 10 % skin
// is reused, and only filtered to the radius, while no particle has moved more than half the
// skin since. The lists are then identical to a fresh search, so results (and restarts) do not
// depend on when the last search happened. Used by the moving reference configuration and by
// the artificial viscosity's current-configuration pairs.

#include "particles/NeighbourList.hpp"
#include "particles/Parallel.hpp"
#include "particles/Types.hpp"

#include <vector>

namespace sph
{

template <int D>
class VerletNeighbours
{
public:
    // The pairs within `radius` at x, into `list`.
    void update(const std::vector<Vec<D>>& x, const std::vector<int>& body, double radius,
                NeighbourList& list)
    {
        const double skin = 0.1 * radius;
        if (!(candidateRadius_ == radius + skin && searchedAt_.size() == x.size() &&
              !movedMoreThan(x, 0.5 * skin)))
        {
            candidates_ = NeighbourList(); // the old ones are not needed by the search
            candidates_ = buildNeighbourList<D>(x, body, radius + skin);
            searchedAt_ = x;
            candidateRadius_ = radius + skin;
        }
        filterNeighbourList<D>(candidates_, x, radius, list);
    }
    const NeighbourList& update(const std::vector<Vec<D>>& x, const std::vector<int>& body,
                                double radius)
    {
        update(x, body, radius, list_);
        return list_;
    }
    // Forgets the last search (the next update searches afresh).
    void clear()
    {
        candidates_ = NeighbourList();
        searchedAt_.clear();
        candidateRadius_ = 0.0;
    }

private:
    bool movedMoreThan(const std::vector<Vec<D>>& x, double distance) const
    {
        const double limit2 = distance * distance;
        const std::size_t n = x.size();
        std::size_t moved = 0;
#pragma omp parallel for schedule(static) reduction(+ : moved) if (useThreads(n))
        for (std::size_t a = 0; a < n; ++a)
        {
            moved += (x[a] - searchedAt_[a]).squaredNorm() >= limit2 ? 1 : 0;
        }
        return moved > 0;
    }

    NeighbourList candidates_;
    NeighbourList list_;
    std::vector<Vec<D>> searchedAt_;
    double candidateRadius_ = 0.0;
};

} // namespace sph
