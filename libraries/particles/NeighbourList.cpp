#include "particles/Parallel.hpp"
#include "particles/NeighbourList.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sph
{

std::size_t NeighbourList::maxCount() const
{
    std::size_t result = 0;
    for (std::size_t a = 0; a + 1 < offsets.size(); ++a)
    {
        result = std::max<std::size_t>(result, offsets[a + 1] - offsets[a]);
    }
    return result;
}

namespace
{

// A uniform grid of cells over the bounding box of `points`, with the points sorted by cell.
// The cells are a millionth wider than asked: two points closer than `cellSize` then always fall
// in adjacent cells, whatever the rounding of their cell coordinates (relative error below
// 1e-9 with at most 10^6 cells per direction). Without that margin a pair a hair's breadth
// inside the radius is found or not depending on where the grid starts, that is on which other
// points are searched: a distributed run's ranks, holding different points, would then differ
// from the serial run (a lattice pair at exactly the support radius did).
template <int D>
class CellGrid
{
public:
    CellGrid(const std::vector<Vec<D>>& points, double cellSize) : cellSize_(cellSize * (1.0 + 1e-6))
    {
        if (!(cellSize > 0.0) || !std::isfinite(cellSize))
        {
            throw std::invalid_argument("neighbour search radius must be positive and finite");
        }
        lower_.setConstant(std::numeric_limits<double>::max());
        Vec<D> upper = Vec<D>::Constant(std::numeric_limits<double>::lowest());
        for (const auto& p : points)
        {
            lower_ = lower_.cwiseMin(p);
            upper = upper.cwiseMax(p);
        }
        if (points.empty())
        {
            lower_.setZero();
            upper.setZero();
        }
        std::size_t cells = 1;
        for (int d = 0; d < D; ++d)
        {
            // Cap the grid size: a sparse far-flung cloud would otherwise allocate huge grids.
            const double span = (upper[d] - lower_[d]) / cellSize_;
            dims_[d] = static_cast<long>(std::min(span, 1.0e6)) + 1;
            cells *= static_cast<std::size_t>(dims_[d]);
        }
        if (cells > 64 * points.size() + 1024)
        {
            // Too sparse for a dense grid: grow the cells (correct, just less selective).
            const double factor = std::pow(static_cast<double>(cells) /
                                               static_cast<double>(64 * points.size() + 1024),
                                           1.0 / D);
            cellSize_ *= factor * 1.01;
            cells = 1;
            for (int d = 0; d < D; ++d)
            {
                dims_[d] = static_cast<long>((upper[d] - lower_[d]) / cellSize_) + 1;
                cells *= static_cast<std::size_t>(dims_[d]);
            }
        }
        start_.assign(cells + 1, 0);
        cellOf_.resize(points.size());
        for (std::size_t i = 0; i < points.size(); ++i)
        {
            cellOf_[i] = cellIndex(coordinates(points[i]));
            ++start_[cellOf_[i] + 1];
        }
        for (std::size_t c = 0; c < cells; ++c)
        {
            start_[c + 1] += start_[c];
        }
        sorted_.resize(points.size());
        std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
        for (std::size_t i = 0; i < points.size(); ++i)
        {
            sorted_[fill[cellOf_[i]]++] = static_cast<std::uint32_t>(i);
        }
    }

    std::array<long, D> coordinates(const Vec<D>& p) const
    {
        std::array<long, D> c{};
        for (int d = 0; d < D; ++d)
        {
            const long value = static_cast<long>(std::floor((p[d] - lower_[d]) / cellSize_));
            c[d] = std::clamp(value, -1L, dims_[d]); // points outside fall into a border ring
        }
        return c;
    }

    // Calls visit(j) for every point in the cells around `p` (3^D cells).
    template <class Visit>
    void forEachNear(const Vec<D>& p, Visit&& visit) const
    {
        const std::array<long, D> centre = coordinates(p);
        std::array<long, D> offset{};
        offset.fill(-1);
        while (true)
        {
            bool inside = true;
            std::array<long, D> c{};
            for (int d = 0; d < D; ++d)
            {
                c[d] = centre[d] + offset[d];
                inside = inside && c[d] >= 0 && c[d] < dims_[d];
            }
            if (inside)
            {
                const std::size_t cell = cellIndex(c);
                for (std::size_t k = start_[cell]; k < start_[cell + 1]; ++k)
                {
                    visit(sorted_[k]);
                }
            }
            int d = 0;
            while (d < D && offset[d] == 1)
            {
                offset[d] = -1;
                ++d;
            }
            if (d == D)
            {
                break;
            }
            ++offset[d];
        }
    }

private:
    std::size_t cellIndex(const std::array<long, D>& c) const
    {
        std::size_t index = 0;
        for (int d = D - 1; d >= 0; --d)
        {
            const long clamped = std::clamp(c[d], 0L, dims_[d] - 1);
            index = index * static_cast<std::size_t>(dims_[d]) + static_cast<std::size_t>(clamped);
        }
        return index;
    }

    double cellSize_;
    Vec<D> lower_;
    std::array<long, D> dims_{};
    std::vector<std::size_t> start_;
    std::vector<std::size_t> cellOf_;
    std::vector<std::uint32_t> sorted_;
};

// The per-thread buffers of a one-pass search (one per thread, owned by the calling thread),
// kept between calls: contact searches its cross lists every step, and allocating and
// page-faulting the buffers each step would cost more than the search. (Its lists are short:
// the particles near another body.)
thread_local std::vector<std::vector<std::uint32_t>> searchBuffers;

// Fills the CSR list in one search pass: each thread searches a contiguous block of particles
// into its own buffer, then the buffers are copied in block order, so the result is the same
// for any thread count.
template <int D, class Candidates>
void fillLists(std::size_t n, Candidates&& candidates, NeighbourList& list)
{
    list.offsets.assign(n + 1, 0);
    std::vector<std::vector<std::uint32_t>>& blocks = searchBuffers;
#pragma omp parallel if (useThreads(n))
    {
#pragma omp single
        {
            blocks.resize(static_cast<std::size_t>(omp_get_num_threads()));
            for (auto& block : blocks)
            {
                block.clear();
            }
        }
        const std::size_t threads = blocks.size();
        const std::size_t thread = static_cast<std::size_t>(omp_get_thread_num());
        const std::size_t first = n * thread / threads;
        const std::size_t last = n * (thread + 1) / threads;
        std::vector<std::uint32_t>& found = blocks[thread];
        for (std::size_t a = first; a < last; ++a)
        {
            const std::size_t before = found.size();
            candidates(a, found);
            list.offsets[a + 1] = static_cast<std::uint32_t>(found.size() - before);
        }
    }
    for (std::size_t a = 0; a < n; ++a)
    {
        list.offsets[a + 1] += list.offsets[a];
    }
    list.indices.resize(list.offsets[n]);
    const std::size_t threads = blocks.size();
#pragma omp parallel for schedule(static, 1) if (threads > 1)
    for (std::size_t thread = 0; thread < threads; ++thread)
    {
        const std::size_t first = n * thread / threads;
        std::copy(blocks[thread].begin(), blocks[thread].end(),
                  list.indices.begin() + list.offsets[first]);
    }
}

template <int D, class Candidates>
NeighbourList fillLists(std::size_t n, Candidates&& candidates)
{
    NeighbourList list;
    fillLists<D>(n, std::forward<Candidates>(candidates), list);
    return list;
}

} // namespace

// Two passes over the cells, counting then filling each particle's slots in place: no buffer
// besides the list (a per-thread copy of it would double the peak of a rebuild, 0.5 kB per
// particle in 3D). The search runs once (a fixed reference) or rarely (a moving reference's
// candidates), so searching twice costs little.
template <int D>
NeighbourList buildNeighbourList(const std::vector<Vec<D>>& x, const std::vector<int>& body,
                                 double radius)
{
    const CellGrid<D> grid(x, radius);
    const double radius2 = radius * radius;
    const std::size_t n = x.size();
    const auto near = [&](std::size_t a, std::uint32_t b) {
        return b != a && body[b] == body[a] && (x[b] - x[a]).squaredNorm() < radius2;
    };
    NeighbourList list;
    list.offsets.assign(n + 1, 0);
#pragma omp parallel for schedule(static) if (useThreads(n))
    for (std::size_t a = 0; a < n; ++a)
    {
        std::uint32_t count = 1; // the particle itself
        grid.forEachNear(x[a], [&](std::uint32_t b) { count += near(a, b) ? 1 : 0; });
        list.offsets[a + 1] = count;
    }
    for (std::size_t a = 0; a < n; ++a)
    {
        list.offsets[a + 1] += list.offsets[a];
    }
    list.indices.resize(list.offsets[n]);
#pragma omp parallel for schedule(static) if (useThreads(n))
    for (std::size_t a = 0; a < n; ++a)
    {
        std::uint32_t* slot = &list.indices[list.offsets[a]];
        *slot++ = static_cast<std::uint32_t>(a);
        std::uint32_t* first = slot;
        grid.forEachNear(x[a], [&](std::uint32_t b) {
            if (near(a, b))
            {
                *slot++ = b;
            }
        });
        std::sort(first, slot);
    }
    return list;
}

template <int D>
NeighbourList filterNeighbourList(const NeighbourList& candidates, const std::vector<Vec<D>>& x,
                                  double radius)
{
    NeighbourList list;
    filterNeighbourList<D>(candidates, x, radius, list);
    return list;
}

template <int D>
void filterNeighbourList(const NeighbourList& candidates, const std::vector<Vec<D>>& x,
                         double radius, NeighbourList& into)
{
    // A particle keeps a subset of its candidates, so each thread writes its block's pairs into
    // `into` from where the block's candidates start, never reaching the next block; the blocks
    // are then moved down in order to close the gaps. No buffer besides the list itself: a
    // moving reference filters every step, and in 3D a copy of the list costs 0.3-0.5 kB per
    // particle. The result is the same for any thread count.
    const double radius2 = radius * radius;
    const std::size_t n = x.size();
    into.offsets.assign(n + 1, 0);
    resizePairArray(into.indices, candidates.pairCount());
    std::vector<std::size_t> blockFirst(1, 0);
#pragma omp parallel if (useThreads(n))
    {
        const std::size_t threads = static_cast<std::size_t>(omp_get_num_threads());
        const std::size_t thread = static_cast<std::size_t>(omp_get_thread_num());
#pragma omp single
        {
            blockFirst.resize(threads + 1);
            for (std::size_t t = 0; t <= threads; ++t)
            {
                blockFirst[t] = n * t / threads;
            }
        }
        std::size_t cursor = blockFirst[thread] < n ? candidates.begin(blockFirst[thread]) : 0;
        for (std::size_t a = blockFirst[thread]; a < blockFirst[thread + 1]; ++a)
        {
            const std::size_t first = candidates.begin(a);
            const std::size_t start = cursor;
            into.indices[cursor++] = candidates.indices[first]; // the particle itself
            for (std::size_t k = first + 1; k < candidates.end(a); ++k)
            {
                const std::uint32_t b = candidates.indices[k];
                if ((x[b] - x[a]).squaredNorm() < radius2)
                {
                    into.indices[cursor++] = b;
                }
            }
            into.offsets[a + 1] = static_cast<std::uint32_t>(cursor - start);
        }
    }
    for (std::size_t a = 0; a < n; ++a)
    {
        into.offsets[a + 1] += into.offsets[a];
    }
    for (std::size_t t = 0; t + 1 < blockFirst.size(); ++t)
    {
        const std::size_t first = blockFirst[t];
        const std::size_t last = blockFirst[t + 1];
        if (first < last && into.offsets[first] != candidates.begin(first))
        {
            std::copy(into.indices.begin() + candidates.begin(first),
                      into.indices.begin() + candidates.begin(first) + (into.offsets[last] - into.offsets[first]),
                      into.indices.begin() + into.offsets[first]);
        }
    }
    into.indices.resize(into.offsets[n]);
}

template <int D>
NeighbourList buildCrossNeighbourList(const std::vector<Vec<D>>& query,
                                      const std::vector<Vec<D>>& source, double radius)
{
    const CellGrid<D> grid(source, radius);
    const double radius2 = radius * radius;
    return fillLists<D>(query.size(), [&](std::size_t a, std::vector<std::uint32_t>& found) {
        const std::size_t first = found.size();
        grid.forEachNear(query[a], [&](std::uint32_t b) {
            if ((source[b] - query[a]).squaredNorm() < radius2)
            {
                found.push_back(b);
            }
        });
        std::sort(found.begin() + static_cast<long>(first), found.end());
    });
}

template NeighbourList buildNeighbourList<1>(const std::vector<Vec<1>>&, const std::vector<int>&, double);
template NeighbourList buildNeighbourList<2>(const std::vector<Vec<2>>&, const std::vector<int>&, double);
template NeighbourList buildNeighbourList<3>(const std::vector<Vec<3>>&, const std::vector<int>&, double);
template void filterNeighbourList<1>(const NeighbourList&, const std::vector<Vec<1>>&, double, NeighbourList&);
template void filterNeighbourList<2>(const NeighbourList&, const std::vector<Vec<2>>&, double, NeighbourList&);
template void filterNeighbourList<3>(const NeighbourList&, const std::vector<Vec<3>>&, double, NeighbourList&);
template NeighbourList filterNeighbourList<1>(const NeighbourList&, const std::vector<Vec<1>>&, double);
template NeighbourList filterNeighbourList<2>(const NeighbourList&, const std::vector<Vec<2>>&, double);
template NeighbourList filterNeighbourList<3>(const NeighbourList&, const std::vector<Vec<3>>&, double);
template NeighbourList buildCrossNeighbourList<1>(const std::vector<Vec<1>>&, const std::vector<Vec<1>>&, double);
template NeighbourList buildCrossNeighbourList<2>(const std::vector<Vec<2>>&, const std::vector<Vec<2>>&, double);
template NeighbourList buildCrossNeighbourList<3>(const std::vector<Vec<3>>&, const std::vector<Vec<3>>&, double);

} // namespace sph
