// The close-pair energy in a run (docs/theory/impenetrability.md): where no pair comes closer
// than the distance (the default, 0.5) — the colliding rings, elastic, updated-Lagrangian gradF through first
// contact — the run is the one without the key, bit for bit (§I2); with a distance of a whole
// spacing the energy acts, and the run differs (so the comparison can fail). Its energy is in
// the strain energy the audit balances.
#include "solver/SolverCases.hpp"

using namespace sph;

namespace
{

VtuData runRings(const std::filesystem::path& folder, const std::vector<std::string>& more)
{
    std::vector<std::string> arguments{"-set", "formulation.type=updatedLagrangian", "-set",
                                       "endTime=0.008", "-set", "writeInterval=1"};
    arguments.insert(arguments.end(), more.begin(), more.end());
    return test::runCoarseRings(folder, arguments);
}

} // namespace

TEST_CASE("impenetrability leaves a run without close pairs unchanged, bit for bit",
          "[impenetrability]")
{
    test::TempDir without;
    test::TempDir half;
    test::TempDir whole;
    const VtuData a = runRings(without.path(), {});
    const VtuData b = runRings(half.path(), {"-set", "sphSchemes.impenetrability={ }"});
    test::requireIdenticalState(a, b);
    CHECK(a.fieldData.at("restart:contactWork").values.at(0) != 0.0); // the rings touched
    const VtuData c = runRings(whole.path(), {"-set", "sphSchemes.impenetrability={ distance 1; }"});
    REQUIRE(c.points.size() == a.points.size());
    CHECK(c.points != a.points);
}

TEST_CASE("impenetrability with distance 0 is off: the run without the key, bit for bit",
          "[impenetrability]")
{
    // What a case that names the energy uses to switch it off (a study level, the command line):
    // with a whole spacing the same rings differ (above), with 0 they are the run without it.
    test::TempDir whole;
    test::TempDir off;
    test::TempDir without;
    const VtuData a = runRings(whole.path(), {"-set", "sphSchemes.impenetrability={ distance 1; }"});
    const VtuData b = runRings(off.path(), {"-set", "sphSchemes.impenetrability={ distance 0; }"});
    const VtuData c = runRings(without.path(), {});
    test::requireIdenticalState(b, c);
    CHECK(a.points != b.points);
}
