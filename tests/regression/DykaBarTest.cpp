// The Dyka bar tutorial (seed §3.1, spec §11.1) under CTest, against the exact solution:
//   - total energy conserved to 1e-5 relative over 5 ms (total-Lagrangian CSPH);
//   - tip period within 3 % of 4L/c;
//   - the tip error decreases with resolution: 40, 80, 160, 320 particles.
#include "support/CaseRunner.hpp"

#include <cmath>
#include <iostream>

using namespace sph;

namespace
{

struct DykaResult
{
    double maxDrift;
    double maxError; // L∞ of the tip displacement error over the run
    double rmsError;
    std::vector<double> downCrossings;
};

DykaResult runDyka(int particles, const std::vector<std::string>& extra = {})
{
    test::TempDir dir;
    const auto caseDir = test::copyTutorial("bar1D/dykaBar", dir.path());
    REQUIRE(test::runParticles(caseDir, {"-set", "bar.n=" + std::to_string(particles)}) == 0);
    std::vector<std::string> args{"-set", "writeInterval=1"};
    args.insert(args.end(), extra.begin(), extra.end());
    REQUIRE(test::runSolver(caseDir, args) == 0);
    DykaResult result{0.0, 0.0, 0.0, {}};
    const auto energy = test::readTable(caseDir / "postProcessing/energy/energy.dat");
    for (double drift : energy.column("drift"))
    {
        result.maxDrift = std::max(result.maxDrift, std::abs(drift));
    }
    const auto tip = test::readTable(caseDir / "postProcessing/tipError/tipError.dat");
    const auto time = tip.column("time");
    const auto u = tip.column("u_numeric");
    const auto error = tip.column("u_error");
    double sum = 0.0;
    for (std::size_t i = 0; i < error.size(); ++i)
    {
        result.maxError = std::max(result.maxError, std::abs(error[i]));
        sum += error[i] * error[i];
        if (i > 0 && u[i - 1] > 0.0 && u[i] <= 0.0)
        {
            result.downCrossings.push_back(time[i - 1] +
                                           u[i - 1] * (time[i] - time[i - 1]) / (u[i - 1] - u[i]));
        }
    }
    result.rmsError = std::sqrt(sum / static_cast<double>(error.size()));
    return result;
}

const double amplitude = 9.3734e-4;     // v0 (L - x_s)/c, spec §11.1
const double period = 4 * 0.1333 / std::sqrt(3.0e4); // 4L/c

} // namespace

TEST_CASE("Dyka bar: energy conserved and tip period right at 40 particles", "[dyka]")
{
    const DykaResult r = runDyka(40);
    std::cout << "dyka 40: max |energy drift| " << r.maxDrift << ", tip error Linf/amplitude "
              << r.maxError / amplitude << "\n";
    CHECK(r.maxDrift < 1e-5);
    REQUIRE(r.downCrossings.size() >= 2);
    const double measured = r.downCrossings[1] - r.downCrossings[0];
    std::cout << "dyka 40: tip period " << measured << " s vs 4L/c = " << period << " s ("
              << 100 * (measured / period - 1) << " %)\n";
    CHECK(std::abs(measured / period - 1.0) < 0.03);
}

TEST_CASE("Dyka bar: the tip error decreases with resolution", "[dyka]")
{
    double previousMax = 1e9;
    double previousRms = 1e9;
    for (int n : {40, 80, 160, 320})
    {
        const DykaResult r = runDyka(n);
        std::cout << "dyka " << n << ": tip error Linf/amplitude " << r.maxError / amplitude
                  << ", RMS/amplitude " << r.rmsError / amplitude << ", energy drift "
                  << r.maxDrift << "\n";
        CHECK(r.maxError < 0.75 * previousMax);
        CHECK(r.rmsError < 0.75 * previousRms);
        CHECK(r.maxDrift < 1e-5);
        previousMax = r.maxError;
        previousRms = r.rmsError;
    }
}
