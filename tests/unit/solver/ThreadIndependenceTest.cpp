// Results do not depend on the number of threads (issue 7): every loop gathers into its own
// particle, reductions are ordered, so one and two threads give the same bits. The coarse
// rings (1120 particles, above the size at which loops use threads) through first contact.
#include "io/PvdSeries.hpp"
#include "io/VtuFile.hpp"
#include "solver/SolverCases.hpp"

using namespace sph;

namespace
{

VtuData runRings(const std::filesystem::path& folder, const std::string& threads,
                 const std::string& scheme)
{
    const auto caseDir = test::copyTutorial("rings2D/collidingRings", folder);
    REQUIRE(test::runParticles(caseDir, {"-set", "ringA.spacing=2e-3", "-set", "ringB.spacing=2e-3"}) == 0);
    REQUIRE(test::runSolver(caseDir, {"-threads", threads, "-set", "stabilisation.type=" + scheme,
                                      "-set", "endTime=0.008", "-set", "writeInterval=1"}) == 0);
    PvdSeries series(caseDir / "VTK" / "collidingRings.pvd");
    series.load();
    return readVtu(caseDir / "VTK" / series.entries().back().file);
}

} // namespace

TEST_CASE("one and two threads give bit-identical results", "[threads]")
{
    for (const std::string scheme : {"gradF", "none"})
    {
        INFO(scheme);
        test::TempDir one;
        test::TempDir two;
        const VtuData a = runRings(one.path(), "1", scheme);
        const VtuData b = runRings(two.path(), "2", scheme);
        REQUIRE(a.pointCount() == 1120);
        test::requireIdenticalState(a, b);
        CHECK(a.fieldData.at("restart:contactWork").values.at(0) != 0.0); // the rings touched
    }
}
