#include "core/Suggest.hpp"

#include <catch2/catch.hpp>

using namespace sph;

TEST_CASE("edit distance counts insertions, deletions, substitutions, swaps", "[suggest]")
{
    CHECK(editDistance("vidal", "vidal") == 0);
    CHECK(editDistance("vidall", "vidal") == 1);
    CHECK(editDistance("vdial", "vidal") == 1); // swap
    CHECK(editDistance("GradF", "gradF") == 0); // case-insensitive
    CHECK(editDistance("", "abc") == 3);
}

TEST_CASE("closest match suggests plausible typos only", "[suggest]")
{
    const std::vector<std::string> names{"gradF", "hourglass", "none", "vidal"};
    CHECK(closestMatch("vidall", names) == std::optional<std::string>("vidal"));
    CHECK(closestMatch("hourgalss", names) == std::optional<std::string>("hourglass"));
    CHECK(closestMatch("gradf", names) == std::optional<std::string>("gradF"));
    CHECK_FALSE(closestMatch("somethingElse", names));
    CHECK(didYouMean("nnoe", names) == "Did you mean 'none'?");
    CHECK(joinSorted({"b", "a", "c"}) == "a, b, c");
}
