#pragma once
// Neighbour lists in compressed-row form. Each particle's list starts with the particle itself
// (the sums of the spec run over b ∈ N(a) including a) followed by the other particles of the
// SAME body within the search radius, in increasing index order, so that results do not depend
// on how the search visited the cells.

#include "particles/Types.hpp"

#include <cstdint>
#include <vector>

namespace sph
{

struct NeighbourList
{
    std::vector<std::uint32_t> offsets; // size N + 1
    std::vector<std::uint32_t> indices; // all lists, back to back

    std::size_t particleCount() const { return offsets.empty() ? 0 : offsets.size() - 1; }
    std::size_t pairCount() const { return indices.size(); }
    std::size_t begin(std::size_t a) const { return offsets[a]; }
    std::size_t end(std::size_t a) const { return offsets[a + 1]; }
    std::size_t count(std::size_t a) const { return offsets[a + 1] - offsets[a]; }
    std::size_t maxCount() const;
};

// Resizes a per-pair array that is resized again whenever the lists change (a moving
// reference: every step). When it must grow it grows to the new size plus 1/16:
// std::vector::resize would double it, so a list that gained one pair would keep up to twice
// its memory for the rest of the run.
template <class T>
void resizePairArray(std::vector<T>& values, std::size_t size)
{
    if (size > values.capacity())
    {
        values.reserve(size + size / 16);
    }
    values.resize(size);
}

// Cell-list search, O(N): every particle against the particles of its own and the adjacent
// cells (cell size = radius). Pairs with |x_a - x_b| < radius and body[a] == body[b].
template <int D>
NeighbourList buildNeighbourList(const std::vector<Vec<D>>& x, const std::vector<int>& body,
                                 double radius);

// The pairs of `candidates` (a list built with a larger radius) that are within `radius`
// at positions x: identical to buildNeighbourList(x, body, radius) while every pair within
// `radius` is among the candidates.
template <int D>
NeighbourList filterNeighbourList(const NeighbourList& candidates, const std::vector<Vec<D>>& x,
                                  double radius);
// The same into an existing list, reusing its memory (no allocation once it has grown).
template <int D>
void filterNeighbourList(const NeighbourList& candidates, const std::vector<Vec<D>>& x,
                         double radius, NeighbourList& into);

// Same, between two point sets: for each point of `query`, the points of `source` within
// `radius` (no self entry, no body filter). Used for contact between bodies.
template <int D>
NeighbourList buildCrossNeighbourList(const std::vector<Vec<D>>& query,
                                      const std::vector<Vec<D>>& source, double radius);

} // namespace sph
