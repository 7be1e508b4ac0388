// The stability monitor's verdict where F is not the map from the initial positions: gradF
// elasticState moving a plastic material's reference keeps F as a dilation frame
// (docs/theory/gradF-plastic.md §G11), so the zero-energy indicator measures the flow's shear
// and the verdict is the closest pair's alone, saying so; with the paper's kinematics
// (ownHistory, F the total map) the same run is judged on both measures as before.
#include "solver/SolverCases.hpp"

#include <nlohmann/json.hpp>

#include <fstream>

using namespace sph;

namespace
{

nlohmann::json stabilityOf(const std::filesystem::path& folder, const std::string& samples)
{
    const auto caseDir = test::copyTutorial("plasticity2D/impact", folder);
    REQUIRE(test::runParticles(caseDir) == 0);
    REQUIRE(test::runSolver(caseDir, {"-set", "formulation.type=updatedLagrangian", "-set",
                                      "stabilisation.type=gradF", "-set",
                                      "stabilisation.plasticSamples=" + samples, "-set",
                                      "endTime=1.2e-5"}) == 0);
    std::ifstream in(caseDir / "postProcessing" / "summary.json");
    return nlohmann::json::parse(in).at("functions").at("stability");
}

} // namespace

TEST_CASE("stabilityMonitor: with gradF elasticState in plastic flow the verdict is the closest "
          "pair's",
          "[stability][plasticity]")
{
    test::TempDir one;
    test::TempDir two;
    const auto frame = stabilityOf(one.path(), "elasticState");
    const auto total = stabilityOf(two.path(), "ownHistory");
    const std::string reason = frame.at("verdictReason");
    CHECK(reason.find("zero-energy indicator not applicable") != std::string::npos);
    CHECK(reason.find("smallest neighbour distance") != std::string::npos);
    // The indicator is still written, and it is what would have decided the verdict.
    CHECK(frame.at("maxIndicator").get<double>() > 0.5);
    const std::string word = frame.at("verdict");
    CHECK(word != "unstable");
    CHECK(total.at("verdictReason").get<std::string>().find("not applicable") == std::string::npos);
}
