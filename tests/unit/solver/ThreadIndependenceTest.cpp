// Results do not depend on the number of threads (issue 7): every loop gathers into its own
// particle, reductions are ordered, so one and two threads give the same bits. The coarse
// rings (1120 particles, above the size at which loops use threads) through first contact.
// Nor on whether the kernel values per pair are stored or recomputed.
#include "solver/SolverCases.hpp"

using namespace sph;

namespace
{

VtuData runRings(const std::filesystem::path& folder, const std::string& threads,
                 const std::string& scheme, const std::vector<std::string>& more = {})
{
    std::vector<std::string> arguments{"-threads", threads, "-set", "stabilisation.type=" + scheme,
                                       "-set", "endTime=0.008", "-set", "writeInterval=1"};
    arguments.insert(arguments.end(), more.begin(), more.end());
    return test::runCoarseRings(folder, arguments);
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

// `kernelValues recomputed` (formulation) evaluates W and W'/r where they are used instead of
// storing them per pair: the same numbers from the same code, so the same run, bit for bit.
TEST_CASE("recomputed kernel values give the stored ones' results bit for bit", "[threads]")
{
    for (const std::string formulation : {"updatedLagrangian", "totalLagrangian"})
    {
        for (const std::string scheme : {"gradF", "none", "hourglass"})
        {
            INFO(formulation << " " << scheme);
            test::TempDir stored;
            test::TempDir recomputed;
            const std::vector<std::string> chosen{"-set", "formulation.type=" + formulation};
            std::vector<std::string> recompute = chosen;
            recompute.insert(recompute.end(), {"-set", "formulation.kernelValues=recomputed"});
            const VtuData a = runRings(stored.path(), "2", scheme, chosen);
            const VtuData b = runRings(recomputed.path(), "2", scheme, recompute);
            test::requireIdenticalState(a, b);
        }
    }
}
