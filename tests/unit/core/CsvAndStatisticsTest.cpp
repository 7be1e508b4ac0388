// RFC 4180 fields of results.csv and the median of repeated measurements (issue 12 item 13).
#include "core/Statistics.hpp"
#include "io/Csv.hpp"

#include "support/TestSupport.hpp"

#include <cmath>

using namespace sph;

TEST_CASE("csv fields: quoted only when needed, quotes doubled (RFC 4180)", "[csv]")
{
    CHECK(csvField("pass") == "pass");
    CHECK(csvField("") == "");
    CHECK(csvField("fail: a, b") == "\"fail: a, b\"");
    CHECK(csvField("det F = \"-0.2\"") == "\"det F = \"\"-0.2\"\"\"");
    CHECK(csvField("two\nlines") == "\"two\nlines\"");
    CHECK(csvField("cr\rhere") == "\"cr\rhere\"");
}

TEST_CASE("median of an odd and an even count, and of none", "[statistics]")
{
    CHECK(median({3.0, 1.0, 2.0}) == 2.0);
    CHECK(median({4.0, 1.0, 3.0, 2.0}) == 2.5); // the mean of the two middle values
    CHECK(median({5.0}) == 5.0);
    CHECK(median({1.0, 2.0}) == 1.5);
    CHECK(std::isnan(median({})));
}
