// The neighbour search (particles/NeighbourList.hpp): a particle's list is every particle of its
// body within the radius, in increasing index order, whatever other points are searched with
// it. A distributed run searches a different set of points on each rank (its own and its
// ghosts); its lists must still be the serial run's, bit for bit, or the sums differ.
#include "particles/NeighbourList.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

using namespace sph;

namespace
{

// Each point's neighbours, as indices into `x` (the first `count` points).
std::vector<std::vector<std::uint32_t>> listsOf(const NeighbourList& list, std::size_t count)
{
    std::vector<std::vector<std::uint32_t>> lists(count);
    for (std::size_t a = 0; a < count; ++a)
    {
        lists[a].assign(list.indices.begin() + static_cast<long>(list.begin(a)),
                        list.indices.begin() + static_cast<long>(list.end(a)));
    }
    return lists;
}

} // namespace

TEST_CASE("neighbour search: a list does not depend on the other points searched", "[numerics]")
{
    // A lattice of decimal spacing (not exact in binary) searched with a radius of exactly three
    // spacings, as sphParticles' lattices are with a cubic spline of hOverDx 1.5: many pairs
    // lie within rounding of the radius, and whether each is found may not depend on where the
    // cell grid starts, which an added far point moves.
    const double spacing = 2e-3;
    const double radius = 3.0 * spacing;
    std::vector<Vec<2>> x;
    for (int i = 0; i < 30; ++i)
    {
        for (int j = 0; j < 12; ++j)
        {
            x.emplace_back(0.005 + spacing * i, -0.04 + spacing * j);
        }
    }
    const std::size_t count = x.size();
    const std::vector<int> body(count, 0);
    const auto alone = listsOf(buildNeighbourList<2>(x, body, radius), count);
    std::size_t atRadius = 0;
    for (std::size_t a = 0; a < count; ++a)
    {
        for (const std::uint32_t b : alone[a])
        {
            atRadius += (x[b] - x[a]).norm() > 0.999 * radius ? 1 : 0;
        }
    }
    CHECK(atRadius > 0); // the lattice does have pairs at the radius, and they are found

    for (int k = 1; k <= 200; ++k)
    {
        std::vector<Vec<2>> more = x;
        std::vector<int> bodies = body;
        more.emplace_back(-0.0371 * k / 7.0, -0.05 - 1.3e-4 * k); // another body: no neighbour
        bodies.push_back(1);
        const auto withOther = listsOf(buildNeighbourList<2>(more, bodies, radius), count);
        INFO("extra point " << k);
        REQUIRE(withOther == alone);
        const auto cross = listsOf(buildCrossNeighbourList<2>(x, more, radius), count);
        for (std::size_t a = 0; a < count; ++a)
        {
            // The cross list has no self entry; otherwise the same points.
            std::vector<std::uint32_t> expected(alone[a].begin() + 1, alone[a].end());
            expected.push_back(static_cast<std::uint32_t>(a));
            std::sort(expected.begin(), expected.end());
            REQUIRE(cross[a] == expected);
        }
    }
}
