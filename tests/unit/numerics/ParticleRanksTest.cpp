// What a model sees of a distributed run (particles/ParticleRanks.hpp), without MPI: the serial
// default changes nothing, and a rank's view finds its owned particles by global index, skips
// its ghosts, and takes a probe's values from the rank that owns it.
#include "particles/ParticleRanks.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace sph;

TEST_CASE("particle ranks: the serial view is the identity", "[numerics]")
{
    const ParticleRanks serial;
    CHECK_FALSE(serial.distributed());
    CHECK(serial.counts(7));
    CHECK(serial.global(7) == 7);
    CHECK(serial.localOwned(7) == std::optional<std::size_t>(7));
    std::vector<double> values{1.0, -2.0};
    serial.minimum(values);
    serial.maximum(values);
    serial.sum(values);
    serial.shareWithGhosts(values);
    CHECK(values == std::vector<double>{1.0, -2.0});
    CHECK(serial.onWriter(values) == values);
    const auto probes = serial.fromOwners({1, 0}, 2, [](std::size_t a, double* out) {
        out[0] = 10.0 * static_cast<double>(a);
        out[1] = -0.0;
    });
    REQUIRE(probes.size() == 4);
    CHECK(probes[0] == 10.0);
    CHECK(probes[2] == 0.0);
    CHECK(std::signbit(probes[1])); // values pass bit for bit, the sign of zero included
}

TEST_CASE("particle ranks: a rank finds its owned particles by global index", "[numerics]")
{
    // Local particles 0..4 hold global 3 (ghost), 5, 8 (ghost), 9, 12, in increasing order.
    const std::vector<std::uint8_t> owned{0, 1, 0, 1, 1};
    const std::vector<int> globalId{3, 5, 8, 9, 12};
    ParticleRanks rank;
    rank.owned = &owned;
    rank.globalId = &globalId;
    std::vector<double> combined;
    rank.maximumOverRanks = [&](std::vector<double>& values) { combined = values; };
    CHECK(rank.distributed());
    CHECK_FALSE(rank.counts(0));
    CHECK(rank.counts(1));
    CHECK(rank.global(4) == 12);
    CHECK(rank.localOwned(9) == std::optional<std::size_t>(3));
    CHECK_FALSE(rank.localOwned(8)); // a ghost here: its owner answers
    CHECK_FALSE(rank.localOwned(4)); // not here at all
    CHECK_FALSE(rank.localOwned(13));
    const auto probes = rank.fromOwners({12, 8, 5}, 1, [&](std::size_t a, double* out) {
        *out = static_cast<double>(globalId[a]) + 0.5;
    });
    // What this rank contributes to the maximum: its owned probes, -inf for the others.
    REQUIRE(combined.size() == 3);
    CHECK(combined[0] == 12.5);
    CHECK(combined[1] == -std::numeric_limits<double>::infinity());
    CHECK(combined[2] == 5.5);
    CHECK(probes == combined);
}
