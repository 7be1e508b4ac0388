#pragma once
// The energy weights a move of the reference chooses for a particle's samples
// (docs/theory/gradF-plastic.md §G9): of all partitions of unity ω ≥ 0 over the new pairs whose
// energy Σ_b ω_b W_b equals the energy E the samples held before the move, the one nearest to
// the kernel's weights Ŵ in relative entropy,
//
//     ω_b(λ) = Ŵ_b exp(−λ W_b) / Σ_c Ŵ_c exp(−λ W_c),                                 (G9.2)
//
// one scalar λ, found by safeguarded Newton iteration on e(λ) = Σ_b ω_b(λ) W_b, which falls
// strictly from max W to min W (e'(λ) = −Var_ω(W)).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace sph
{

struct EnergyWeightsResult
{
    double lambda = 0.0;   // λ of (G9.2), in the units of 1/W
    double residual = 0.0; // Σ ω W − E left (0 to round-off unless E is out of reach)
    int iterations = 0;
    bool reached = true; // the energy asked for is kept (or, nonIncreasing, not exceeded)
};

// kernel: Ŵ (Σ = 1, ≥ 0), energy: W_b, target: E; the weights into omega (may alias nothing).
// With nonIncreasing, only an energy above E is corrected (ω = Ŵ where Σ Ŵ W ≤ E). resolution:
// the smallest energy density the material resolves (a strain of one ulp, §G22): a difference
// below it is no energy to keep, and the kernel's weights are kept.
inline EnergyWeightsResult chooseEnergyWeights(const double* kernel, const double* energy,
                                               std::size_t count, double target, bool nonIncreasing,
                                               double* omega, double resolution = 0.0)
{
    EnergyWeightsResult result;
    // Energies relative to the kernel's mean, for the exponentials' range.
    double mean = 0.0;
    double below = 0.0; // max (mean − W) over the weighted samples
    double above = 0.0; // max (W − mean)
    for (std::size_t j = 0; j < count; ++j)
    {
        mean += kernel[j] * energy[j];
    }
    for (std::size_t j = 0; j < count; ++j)
    {
        if (kernel[j] > 0.0)
        {
            below = std::max(below, mean - energy[j]);
            above = std::max(above, energy[j] - mean);
        }
    }
    const double spread = std::max(below, above);
    const double goal = target - mean;
    // Round-off of the sums: a few ulps of the energies' magnitude.
    const double tolerance = std::max(8.0 * std::numeric_limits<double>::epsilon() *
                                          (std::abs(mean) + spread + std::abs(target)),
                                      resolution);
    // The sums' arithmetic is spelt out (w u once, its square's sum fused): the digits then do
    // not depend on how the compiler contracts the loop. At λ = 0 (the first pass of every move)
    // exp(−0 u) = 1 exactly for finite u, so no exp is needed.
    const auto weightsAt = [&](double lambda, double& e, double& variance) {
        double z = 0.0;
        double first = 0.0;
        double second = 0.0;
        for (std::size_t j = 0; j < count; ++j)
        {
            const double u = energy[j] - mean;
            const double factor = lambda == 0.0 && std::isfinite(u) ? 1.0 : std::exp(-lambda * u);
            const double w = kernel[j] > 0.0 ? kernel[j] * factor : 0.0;
            omega[j] = w;
            z += w;
            const double wu = w * u;
            first += wu;
            second = std::fma(wu, u, second);
        }
        for (std::size_t j = 0; j < count; ++j)
        {
            omega[j] /= z;
        }
        e = first / z;
        variance = std::max(second / z - e * e, 0.0);
    };
    double e = 0.0;
    double variance = 0.0;
    weightsAt(0.0, e, variance);
    if (std::abs(e - goal) <= tolerance || spread == 0.0 || (nonIncreasing && e <= goal))
    {
        std::copy(kernel, kernel + count, omega);
        result.residual = e - goal;
        result.reached = std::abs(e - goal) <= tolerance || (nonIncreasing && e <= goal);
        return result;
    }
    // e(λ) − goal falls with λ; bracket its root where no factor exp(−λ u) overflows: λ ≤ 700 /
    // (mean − min W), −λ ≤ 700 / (max W − mean). An underflow is harmless (that sample's weight
    // is 0; the one with the smallest −λ u keeps a factor ≥ 1), so one outlying energy does not
    // narrow the bracket on its own side (it did, to 700 / spread both ways: a particle whose
    // goal needed a larger λ than its outlier allowed missed it, 2026-11-29).
    const double high0 = below > 0.0 ? 700.0 / below : 700.0 / spread;
    const double low0 = above > 0.0 ? -700.0 / above : -700.0 / spread;
    double low = low0;
    double high = high0;
    double lambda = 0.0;
    for (result.iterations = 1; result.iterations <= 100; ++result.iterations)
    {
        if (e > goal)
        {
            low = lambda;
        }
        else
        {
            high = lambda;
        }
        double next = variance > 0.0 ? lambda + (e - goal) / variance : 0.5 * (low + high);
        if (!(next > low && next < high))
        {
            next = 0.5 * (low + high); // Newton left the bracket
        }
        lambda = next;
        weightsAt(lambda, e, variance);
        if (std::abs(e - goal) <= tolerance || high - low <= 1e-15 * (high0 - low0))
        {
            break;
        }
    }
    result.lambda = lambda;
    result.residual = e - goal;
    result.reached = std::abs(e - goal) <= tolerance || (nonIncreasing && e <= goal);
    return result;
}

} // namespace sph
