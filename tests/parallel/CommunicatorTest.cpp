// The communicator of a distributed run (libraries/parallel): reductions that give the same
// bits on every rank, the broadcast of one rank's diagnosis, and RCB partitions that give each
// rank the same count to within one particle, in boxes that do not overlap.
#include "parallel/Communicator.hpp"
#include "parallel/RcbPartition.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace sph;

TEST_CASE("communicator: minimum, maximum and sums over the ranks", "[parallel]")
{
    const Communicator comm = Communicator::world();
    const int n = comm.size();
    REQUIRE(comm.rank() >= 0);
    REQUIRE(comm.rank() < n);
    CHECK(comm.minimum(10.0 + comm.rank()) == 10.0);
    CHECK(comm.maximum(10.0 + comm.rank()) == 10.0 + (n - 1));
    CHECK(comm.sum(static_cast<long long>(comm.rank() + 1)) == static_cast<long long>(n) * (n + 1) / 2);
    // 0.1 + 0.2 + ... in rank order, on every rank the same bits as this loop.
    double expected = 0.0;
    for (int r = 0; r < n; ++r)
    {
        expected += 0.1 * (r + 1);
    }
    const double sum = comm.sum(0.1 * (comm.rank() + 1));
    CHECK(sum == expected);
    CHECK(comm.maximum(sum) == comm.minimum(sum)); // the same on every rank
    // Element by element: rank r gives (r, -r, 5).
    std::vector<double> low{1.0 * comm.rank(), -1.0 * comm.rank(), 5.0};
    std::vector<double> high = low;
    comm.minimum(low);
    comm.maximum(high);
    CHECK(low == std::vector<double>{0.0, 1.0 - n, 5.0});
    CHECK(high == std::vector<double>{n - 1.0, 0.0, 5.0});
    const std::vector<double> all = comm.gather(static_cast<double>(comm.rank()));
    REQUIRE(all.size() == static_cast<std::size_t>(n));
    for (int r = 0; r < n; ++r)
    {
        CHECK(all[static_cast<std::size_t>(r)] == r);
    }
}

TEST_CASE("communicator: one rank's text reaches every rank", "[parallel]")
{
    const Communicator comm = Communicator::world();
    const int root = comm.size() - 1;
    const std::string mine = comm.rank() == root ? "det F = -0.1 <= 0 at particle 42" : "";
    CHECK(comm.broadcast(mine, root) == "det F = -0.1 <= 0 at particle 42");
    CHECK(comm.broadcast("", 0).empty());
}

TEST_CASE("communicator: values reach the ranks that expect them, point to point", "[parallel]")
{
    // A ring: each rank sends r + 1 values to the next and receives from the previous, whose
    // count it knows; and keeps one value for itself.
    const Communicator comm = Communicator::world();
    const auto n = static_cast<std::size_t>(comm.size());
    const auto me = static_cast<std::size_t>(comm.rank());
    const std::size_t next = (me + 1) % n;
    const std::size_t previous = (me + n - 1) % n;
    std::vector<std::vector<double>> toEach(n);
    std::vector<std::size_t> fromEachCount(n, 0);
    if (n > 1)
    {
        toEach[next].assign(me + 1, 0.5 + static_cast<double>(me));
        fromEachCount[previous] = previous + 1;
    }
    toEach[me].push_back(-1.0);
    fromEachCount[me] = 1;
    const auto fromEach = comm.exchangeKnown(toEach, fromEachCount);
    REQUIRE(fromEach.size() == n);
    CHECK(fromEach[me] == std::vector<double>{-1.0});
    if (n > 1)
    {
        CHECK(fromEach[previous] ==
              std::vector<double>(previous + 1, 0.5 + static_cast<double>(previous)));
    }
    CHECK_THROWS_AS(comm.exchangeKnown(toEach, {}), std::logic_error);
}

TEST_CASE("RCB: every rank gets an equal share, in boxes that do not overlap", "[parallel]")
{
    const Communicator comm = Communicator::world();
    const int n = comm.size();
    // A 40 x 25 lattice dealt round-robin (particle g on rank g mod n): the worst start.
    std::vector<Vec<2>> x;
    std::vector<std::uint64_t> id;
    for (std::uint64_t g = 0; g < 1000; ++g)
    {
        if (static_cast<int>(g % static_cast<std::uint64_t>(n)) == comm.rank())
        {
            x.push_back(Vec<2>(0.01 * static_cast<double>(g % 40), 0.01 * static_cast<double>(g / 40)));
            id.push_back(g);
        }
    }
    const std::vector<int> owner = rcbOwners<2>(comm, x, id);
    REQUIRE(owner.size() == x.size());
    // Counts per rank after the move, summed over the ranks.
    std::vector<long long> counts(static_cast<std::size_t>(n), 0);
    for (const int o : owner)
    {
        REQUIRE(o >= 0);
        REQUIRE(o < n);
        ++counts[static_cast<std::size_t>(o)];
    }
    std::vector<long long> total(static_cast<std::size_t>(n), 0);
    for (int r = 0; r < n; ++r)
    {
        total[static_cast<std::size_t>(r)] = comm.sum(counts[static_cast<std::size_t>(r)]);
    }
    const auto [least, most] = std::minmax_element(total.begin(), total.end());
    CHECK(*most - *least <= 1);
    CHECK(comm.sum(static_cast<long long>(x.size())) == 1000);
    // Each rank's box (over the particles every rank sends to it) overlaps no other's: RCB cuts
    // along coordinates, so the boxes of two ranks are separated in at least one direction, or
    // share the cutting line (lattice particles on a cut may go either way, for the balance).
    for (int r = 0; r < n; ++r)
    {
        Vec<2> low = Vec<2>::Constant(1e30), high = Vec<2>::Constant(-1e30);
        for (std::size_t i = 0; i < x.size(); ++i)
        {
            if (owner[i] == r)
            {
                low = low.cwiseMin(x[i]);
                high = high.cwiseMax(x[i]);
            }
        }
        for (int d = 0; d < 2; ++d)
        {
            low[d] = comm.minimum(low[d]);
            high[d] = comm.maximum(high[d]);
        }
        for (int s = r + 1; s < n; ++s)
        {
            Vec<2> lowS = Vec<2>::Constant(1e30), highS = Vec<2>::Constant(-1e30);
            for (std::size_t i = 0; i < x.size(); ++i)
            {
                if (owner[i] == s)
                {
                    lowS = lowS.cwiseMin(x[i]);
                    highS = highS.cwiseMax(x[i]);
                }
            }
            bool separated = false;
            for (int d = 0; d < 2; ++d)
            {
                lowS[d] = comm.minimum(lowS[d]);
                highS[d] = comm.maximum(highS[d]);
                separated = separated || high[d] <= lowS[d] || highS[d] <= low[d];
            }
            INFO("ranks " << r << " and " << s);
            CHECK(separated);
        }
    }
    // The same input gives the same owners (a restart on the same ranks partitions alike).
    CHECK(rcbOwners<2>(comm, x, id) == owner);
}
