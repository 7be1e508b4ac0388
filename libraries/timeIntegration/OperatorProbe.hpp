#pragma once
// The largest frequency of the discrete operator, measured (docs/theory/timeStep.md §T3): power
// iteration on A = M^(-1/2) K M^(-1/2), each product from one force evaluation at perturbed
// positions, one-sided about the level's own force T⁰:
//
//   δx_a = y_a / √m_a,  ε = 1e-6 h / max_a |δx_a|,  (A y)_a ≈ −(T_a(x + ε δx) − T⁰_a) / (ε √m_a),
//   ω̃² = |A y| / |y| of the last product                                         (T3.1, T3.2)
//
// The mode y is kept between probes (warm start) and is the caller's restart data; each probe
// first adds a pseudo-random vector of norm 0.1 drawn from a generator seeded by the step, so
// that a mode newly the stiffest has a component to grow from and a restart draws the same.
// Fixed particles are not degrees of freedom (y_a = 0). Sums in particle order: the result
// does not depend on the number of threads.

#include "particles/Types.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace sph
{

template <int D>
class OperatorProbe
{
public:
    // T at positions x (the internal force, as the level's own evaluation computes it).
    using ForcesAt = std::function<void(const std::vector<Vec<D>>& x, std::vector<Vec<D>>& T)>;

    struct Result
    {
        double omega = 0.0;    // ω̃ of (T3.2) [1/s]
        std::size_t where = 0; // the particle where the mode is largest
    };

    struct Level
    {
        const std::vector<Vec<D>>& x;           // x^n
        const std::vector<Vec<D>>& T0;          // T(x^n)
        const std::vector<double>& m;           // masses
        const std::vector<std::uint8_t>& fixed; // fixed particles
        double h = 0.0;                         // the kernel's smoothing length
        long step = 0;                          // seeds the random part
    };

    // `iterations` products from the kept mode y (resized and drawn afresh if its size is not
    // the particles').
    static Result run(const Level& level, const ForcesAt& forcesAt, int iterations,
                      std::vector<Vec<D>>& y)
    {
        const std::size_t n = level.x.size();
        if (y.size() != n)
        {
            y.assign(n, Vec<D>::Zero());
        }
        addNoise(level, y);
        std::vector<Vec<D>> x(n), T(n), Ay(n);
        Result result;
        for (int it = 0; it < iterations; ++it)
        {
            const double norm = normalise(level, y);
            if (!(norm > 0.0))
            {
                return result; // every particle fixed: nothing moves
            }
            double largest = 0.0;
            for (std::size_t a = 0; a < n; ++a)
            {
                largest = std::max(largest, y[a].norm() / std::sqrt(level.m[a]));
            }
            const double eps = 1e-6 * level.h / largest;
            for (std::size_t a = 0; a < n; ++a)
            {
                x[a] = level.x[a] + (eps / std::sqrt(level.m[a])) * y[a];
            }
            forcesAt(x, T);
            double squared = 0.0;
            for (std::size_t a = 0; a < n; ++a)
            {
                Ay[a] = level.fixed[a] ? Vec<D>::Zero()
                                       : Vec<D>(-(T[a] - level.T0[a]) / (eps * std::sqrt(level.m[a])));
                squared += Ay[a].squaredNorm();
            }
            result.omega = std::sqrt(std::sqrt(squared)); // |A y| with |y| = 1
            y.swap(Ay);
        }
        normalise(level, y);
        double largest = -1.0;
        for (std::size_t a = 0; a < n; ++a)
        {
            if (y[a].norm() > largest)
            {
                largest = y[a].norm();
                result.where = a;
            }
        }
        return result;
    }

private:
    // y ← y/|y| (fixed particles zeroed); returns |y| before.
    static double normalise(const Level& level, std::vector<Vec<D>>& y)
    {
        double squared = 0.0;
        for (std::size_t a = 0; a < y.size(); ++a)
        {
            if (level.fixed[a])
            {
                y[a].setZero();
            }
            squared += y[a].squaredNorm();
        }
        const double norm = std::sqrt(squared);
        if (norm > 0.0)
        {
            for (auto& v : y)
            {
                v /= norm;
            }
        }
        return norm;
    }

    // y ← y/|y| + 0.1 r/|r|, r uniform in [-½, ½] per component from a 64-bit linear
    // congruential generator (Knuth's MMIX constants) seeded by the step: the same numbers on
    // every machine and after a restart.
    static void addNoise(const Level& level, std::vector<Vec<D>>& y)
    {
        normalise(level, y);
        std::vector<Vec<D>> r(y.size(), Vec<D>::Zero());
        std::uint64_t state = 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint64_t>(level.step);
        for (std::size_t a = 0; a < y.size(); ++a)
        {
            for (int k = 0; k < D; ++k)
            {
                state = state * 6364136223846793005ULL + 1442695040888963407ULL;
                r[a][k] = level.fixed[a] ? 0.0
                                         : static_cast<double>(state >> 11) * 0x1.0p-53 - 0.5;
            }
        }
        normalise(level, r);
        for (std::size_t a = 0; a < y.size(); ++a)
        {
            y[a] += 0.1 * r[a];
        }
    }
};

} // namespace sph
