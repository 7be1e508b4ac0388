// The number formats of messages, summaries and study tables (core/Format.hpp).
#include "core/Format.hpp"

#include <catch2/catch.hpp>

#include <limits>

using namespace sph;

TEST_CASE("formatNumber is as short as the value allows", "[format]")
{
    CHECK(formatNumber(1.67e6) == "1.67e+06");
    CHECK(formatNumber(1.5) == "1.5");
    CHECK(formatNumber(0.001) == "0.001");
    CHECK(formatNumber(0.2955123, 4) == "0.2955");
    CHECK(formatNumber(-std::numeric_limits<double>::infinity()) == "-inf");
}

TEST_CASE("formatFixed and formatScientific keep their decimals", "[format]")
{
    CHECK(formatFixed(17608.0, 0) == "17608");
    CHECK(formatFixed(0.44949, 3) == "0.449");
    CHECK(formatScientific(4.775e-4) == "4.775e-04");
    CHECK(formatScientific(12.6, 1) == "1.3e+01");
}
