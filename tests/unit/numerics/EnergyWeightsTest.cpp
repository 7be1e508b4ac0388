// The energy weights of a reference move (docs/theory/gradF-plastic.md §G9, EnergyWeights.hpp):
//   - they are a partition of unity, positive where the kernel's are, and keep the energy
//     asked for to round-off (G9.1);
//   - they are the kernel's, bit for bit, when the kernel's already keep it, and, with
//     nonIncreasing, wherever the kernel's would lower it;
//   - they are the nearest to the kernel's in relative entropy: every feasible perturbation
//     (Σ δ = 0, Σ δ W = 0) moves them further away (G9.2);
//   - an energy out of reach leaves a residual of the right sign instead of a failure.
#include "stabilisation/gradF/EnergyWeights.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

using namespace sph;

namespace
{

struct Samples
{
    std::vector<double> kernel;
    std::vector<double> energy;
};

// Kernel weights of a one-sided support (some zero) and energies spread over two decades.
Samples randomSamples(unsigned seed, std::size_t count)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    Samples s;
    for (std::size_t j = 0; j < count; ++j)
    {
        s.kernel.push_back(j % 7 == 3 ? 0.0 : std::pow(uniform(random), 3));
        s.energy.push_back(1e5 * (1.0 + 100.0 * uniform(random)));
    }
    const double sum = std::accumulate(s.kernel.begin(), s.kernel.end(), 0.0);
    for (double& w : s.kernel)
    {
        w /= sum;
    }
    return s;
}

double weighted(const std::vector<double>& w, const std::vector<double>& e)
{
    return std::inner_product(w.begin(), w.end(), e.begin(), 0.0);
}

double relativeEntropy(const std::vector<double>& w, const std::vector<double>& kernel)
{
    double sum = 0.0;
    for (std::size_t j = 0; j < w.size(); ++j)
    {
        sum += w[j] > 0.0 ? w[j] * std::log(w[j] / kernel[j]) : 0.0;
    }
    return sum;
}

} // namespace

TEST_CASE("energy weights keep the energy, as a positive partition of unity (G9.1)",
          "[gradF][moveWeights]")
{
    for (unsigned seed = 1; seed <= 20; ++seed)
    {
        const Samples s = randomSamples(seed, 30);
        const double mean = weighted(s.kernel, s.energy);
        for (const double shift : {-0.2, -1e-3, 1e-6, 0.05, 0.3})
        {
            INFO("seed " << seed << ", target = mean × (1 + " << shift << ")");
            const double target = mean * (1.0 + shift);
            std::vector<double> omega(s.kernel.size());
            const EnergyWeightsResult r = chooseEnergyWeights(
                s.kernel.data(), s.energy.data(), s.kernel.size(), target, false, omega.data());
            CHECK(std::abs(weighted(omega, s.energy) - target) < 1e-13 * target);
            CHECK(std::abs(r.residual) < 1e-13 * target);
            CHECK(std::accumulate(omega.begin(), omega.end(), 0.0) == Approx(1.0).epsilon(1e-14));
            for (std::size_t j = 0; j < omega.size(); ++j)
            {
                CHECK(omega[j] >= 0.0);
                CHECK((omega[j] == 0.0) == (s.kernel[j] == 0.0));
            }
            CHECK(r.iterations < 60);
            // The sign of λ: a lower energy weights the low-energy samples up (λ > 0).
            CHECK((r.lambda > 0.0) == (shift < 0.0));
        }
    }
}

TEST_CASE("energy weights are the kernel's where no correction is needed", "[gradF][moveWeights]")
{
    const Samples s = randomSamples(7, 25);
    const double mean = weighted(s.kernel, s.energy);
    std::vector<double> omega(s.kernel.size());
    chooseEnergyWeights(s.kernel.data(), s.energy.data(), s.kernel.size(), mean, false, omega.data());
    CHECK(omega == s.kernel);
    // nonIncreasing: a target above the kernel's energy (the move would lower it) keeps them;
    // one below is corrected.
    chooseEnergyWeights(s.kernel.data(), s.energy.data(), s.kernel.size(), 1.1 * mean, true,
                        omega.data());
    CHECK(omega == s.kernel);
    chooseEnergyWeights(s.kernel.data(), s.energy.data(), s.kernel.size(), 0.9 * mean, true,
                        omega.data());
    CHECK(omega != s.kernel);
    CHECK(weighted(omega, s.energy) == Approx(0.9 * mean).epsilon(1e-13));
    // Equal energies: nothing to choose between.
    const std::vector<double> flat(s.kernel.size(), 3.0);
    const EnergyWeightsResult r = chooseEnergyWeights(s.kernel.data(), flat.data(), flat.size(),
                                                      3.5, false, omega.data());
    CHECK(omega == s.kernel);
    CHECK(r.residual == Approx(-0.5));
}

// (G22.3): samples that hold nothing but round-off (opened ones at the cone's apex: W = 0 or
// 1e-48) have no energy to keep. Without a resolution the iteration puts every weight on the
// sample with the largest round-off; with the material's, E ε², the kernel's weights stay.
TEST_CASE("energy weights keep the kernel's below the energies' resolution (G22.3)",
          "[gradF][moveWeights]")
{
    const Samples s = randomSamples(5, 9);
    std::vector<double> roundOff(s.kernel.size(), 0.0);
    roundOff[4] = 1.36e-48;
    const double target = 1.5e-49;
    std::vector<double> omega(s.kernel.size());
    chooseEnergyWeights(s.kernel.data(), roundOff.data(), roundOff.size(), target, false,
                        omega.data());
    CHECK(omega != s.kernel); // the check has teeth: round-off chose the weights
    const double epsilon = std::numeric_limits<double>::epsilon();
    const EnergyWeightsResult r = chooseEnergyWeights(s.kernel.data(), roundOff.data(),
                                                      roundOff.size(), target, false, omega.data(),
                                                      2.5 * epsilon * epsilon);
    CHECK(omega == s.kernel);
    CHECK(r.reached);
    // Above the resolution nothing changes: the weights of a real energy are the same digits.
    std::vector<double> withResolution(s.kernel.size());
    const double mean = weighted(s.kernel, s.energy);
    chooseEnergyWeights(s.kernel.data(), s.energy.data(), s.kernel.size(), 0.8 * mean, false,
                        omega.data());
    chooseEnergyWeights(s.kernel.data(), s.energy.data(), s.kernel.size(), 0.8 * mean, false,
                        withResolution.data(), 2.5 * epsilon * epsilon);
    CHECK(withResolution == omega);
}

TEST_CASE("energy weights are the nearest to the kernel's in relative entropy (G9.2)",
          "[gradF][moveWeights]")
{
    const Samples s = randomSamples(3, 12);
    const double target = 0.8 * weighted(s.kernel, s.energy);
    std::vector<double> omega(s.kernel.size());
    chooseEnergyWeights(s.kernel.data(), s.energy.data(), s.kernel.size(), target, false,
                        omega.data());
    const double best = relativeEntropy(omega, s.kernel);
    std::mt19937 random(11);
    std::normal_distribution<double> normal;
    std::size_t tried = 0;
    for (int trial = 0; trial < 200; ++trial)
    {
        // A random direction with Σ δ = 0 and Σ δ W = 0 (projected), on the kernel's support.
        std::vector<double> d(omega.size());
        for (std::size_t j = 0; j < d.size(); ++j)
        {
            d[j] = s.kernel[j] > 0.0 ? normal(random) : 0.0;
        }
        // An orthogonal basis of the constraints on the support: 1, and W with its mean removed.
        std::vector<double> one(d.size()), u(d.size());
        double count = 0.0, mean = 0.0;
        for (std::size_t j = 0; j < d.size(); ++j)
        {
            one[j] = s.kernel[j] > 0.0 ? 1.0 : 0.0;
            count += one[j];
            mean += one[j] * s.energy[j];
        }
        for (std::size_t j = 0; j < d.size(); ++j)
        {
            u[j] = one[j] * (s.energy[j] - mean / count);
        }
        for (const std::vector<double>* basis : {&one, &u})
        {
            const double bb = std::inner_product(basis->begin(), basis->end(), basis->begin(), 0.0);
            const double db = std::inner_product(d.begin(), d.end(), basis->begin(), 0.0);
            for (std::size_t j = 0; j < d.size(); ++j)
            {
                d[j] -= db / bb * (*basis)[j];
            }
        }
        // A step small against the smallest weight: the perturbed weights stay positive.
        double smallest = 1.0, largest = 0.0;
        for (std::size_t j = 0; j < d.size(); ++j)
        {
            smallest = s.kernel[j] > 0.0 ? std::min(smallest, omega[j]) : smallest;
            largest = std::max(largest, std::abs(d[j]));
        }
        std::vector<double> other(omega);
        bool positive = true;
        for (std::size_t j = 0; j < d.size(); ++j)
        {
            other[j] += (trial % 2 ? 0.5 : 1e-3) * smallest / largest * d[j];
            positive = positive && (s.kernel[j] == 0.0 || other[j] > 0.0);
        }
        if (!positive)
        {
            continue;
        }
        ++tried;
        REQUIRE(weighted(other, s.energy) == Approx(target).epsilon(1e-9));
        CHECK(relativeEntropy(other, s.kernel) > best);
    }
    CHECK(tried > 100);
}

TEST_CASE("energy weights: an energy out of reach leaves a residual, not a failure",
          "[gradF][moveWeights]")
{
    const Samples s = randomSamples(5, 20);
    const double highest = *std::max_element(s.energy.begin(), s.energy.end());
    std::vector<double> omega(s.kernel.size());
    const EnergyWeightsResult r = chooseEnergyWeights(s.kernel.data(), s.energy.data(),
                                                      s.kernel.size(), 2.0 * highest, false,
                                                      omega.data());
    CHECK(r.residual < 0.0);                  // could not reach it: below
    CHECK(weighted(omega, s.energy) > 0.99 * highest); // as near as the weights can go
    CHECK(std::accumulate(omega.begin(), omega.end(), 0.0) == Approx(1.0).epsilon(1e-14));
}

// A particle's samples after a move of the collapse (10 mm, t = 0.563 s; 2026-11-29): most hold
// nothing (opened sand), one a little, and one new pair far more than all of them. The energy
// to keep needs λ ≈ 1.3 / W of the small one; the old bracket, 700 / spread both ways, stopped
// at 700 / 2108 = 0.33 and left the move 4 % of the particle's energy higher. The outlier's
// factor exp(−λ u) only underflows on that side: it cannot narrow the bracket there.
TEST_CASE("energy weights: one outlying energy does not put the goal out of reach",
          "[gradF][moveWeights]")
{
    const std::vector<double> kernel{0.236, 0.00066, 0.008, 0.0209, 0.144, 0.0028, 0.117,
                                     0.0071, 0.216, 0.0393, 0.00034, 0.00091, 0.2067};
    const double sum = std::accumulate(kernel.begin(), kernel.end(), 0.0);
    std::vector<double> w = kernel;
    for (double& value : w)
    {
        value /= sum;
    }
    const std::vector<double> energy{0.165734, 0.0614296, 0.0, 0.0, 0.0, 0.0, 5.5e-43,
                                     0.0,      0.0,       0.0, 2108.06, 0.0, 0.0};
    const double goal = 0.0334104;
    std::vector<double> omega(w.size());
    const EnergyWeightsResult r =
        chooseEnergyWeights(w.data(), energy.data(), w.size(), goal, false, omega.data());
    INFO("lambda " << r.lambda << ", residual " << r.residual);
    CHECK(r.reached);
    CHECK(std::abs(weighted(omega, energy) - goal) < 1e-12 * goal);
    CHECK(r.lambda > 700.0 / 2108.06); // beyond the old bracket
    CHECK(omega[10] < 1e-300);         // the outlier's weight underflowed, harmlessly
    CHECK(std::accumulate(omega.begin(), omega.end(), 0.0) == Approx(1.0).epsilon(1e-14));
}
