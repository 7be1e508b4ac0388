#pragma once
// The largest frequency of the discrete operator, measured (docs/theory/timeStep.md §T3): power
// iteration on A = M^(-1/2) K M^(-1/2), each product from one force evaluation at perturbed
// positions, one-sided about the level's own force T⁰:
//
//   δx_a = y_a / √m_a,  ε = 1e-6 h / max_a |δx_a|,  (A y)_a ≈ −(T_a(x + ε δx) − T⁰_a) / (ε √m_a),
//   ω̃² = |A y| / |y| of the last product                                         (T3.1, T3.2)
//
// The mode y is kept between probes (warm start) and is the caller's restart data; each probe
// first adds a pseudo-random vector of norm 0.1 drawn from a hash of the step and the particle's
// global index, so that a mode newly the stiffest has a component to grow from, a restart draws
// the same and so does any partition into ranks. Fixed particles are not degrees of freedom
// (y_a = 0). On several ranks each rank visits the particles it owns, the ghosts take their
// owners' y, and the sums are made exact (each term a whole number of 2^-30 of the largest): the
// result does not depend on the ranks or the threads, bit for bit.

#include "particles/ParticleRanks.hpp"
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
        const std::vector<Vec<D>>& x;           // x^n (owned particles and ghosts)
        const std::vector<Vec<D>>& T0;          // T(x^n)
        const std::vector<double>& m;           // masses
        const std::vector<std::uint8_t>& fixed; // fixed particles
        double h = 0.0;                         // the kernel's smoothing length
        long step = 0;                          // seeds the random part
        const ParticleRanks& ranks;             // serial: a default-constructed one
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
            if (!(normalise(level, y) > 0.0))
            {
                return result; // every particle fixed: nothing moves
            }
            std::vector<double> largest{0.0};
            for (std::size_t a = 0; a < n; ++a)
            {
                if (level.ranks.counts(a))
                {
                    largest[0] = std::max(largest[0], y[a].norm() / std::sqrt(level.m[a]));
                }
            }
            level.ranks.maximum(largest);
            const double eps = 1e-6 * level.h / largest[0];
            for (std::size_t a = 0; a < n; ++a)
            {
                x[a] = level.x[a] + (eps / std::sqrt(level.m[a])) * y[a];
            }
            forcesAt(x, T);
            for (std::size_t a = 0; a < n; ++a)
            {
                Ay[a] = level.fixed[a] || !level.ranks.counts(a)
                            ? Vec<D>::Zero()
                            : Vec<D>(-(T[a] - level.T0[a]) / (eps * std::sqrt(level.m[a])));
            }
            result.omega = std::sqrt(norm(level, Ay)); // |A y| with |y| = 1
            y.swap(Ay);
        }
        normalise(level, y);
        double largest = -1.0;
        for (std::size_t a = 0; a < n; ++a)
        {
            if (level.ranks.counts(a) && y[a].norm() > largest)
            {
                largest = y[a].norm();
                result.where = a;
            }
        }
        return result;
    }

private:
    // |v| over the owned particles, exact in any order: each |v_a|² rounded to a whole number
    // of quanta 2^-30 of the largest (the sum of up to 2^23 of them is exact in a double).
    static double norm(const Level& level, const std::vector<Vec<D>>& v)
    {
        std::vector<double> largest{0.0};
        for (std::size_t a = 0; a < v.size(); ++a)
        {
            if (level.ranks.counts(a))
            {
                largest[0] = std::max(largest[0], v[a].squaredNorm());
            }
        }
        level.ranks.maximum(largest);
        if (!(largest[0] > 0.0))
        {
            return 0.0;
        }
        const double quantum = largest[0] * 0x1.0p-30;
        std::vector<double> quanta{0.0};
        for (std::size_t a = 0; a < v.size(); ++a)
        {
            if (level.ranks.counts(a))
            {
                quanta[0] += std::nearbyint(v[a].squaredNorm() / quantum);
            }
        }
        level.ranks.sum(quanta);
        return std::sqrt(quanta[0] * quantum);
    }

    // y ← y/|y| over the owned particles (fixed ones zeroed), the ghosts' y their owners';
    // returns |y| before.
    static double normalise(const Level& level, std::vector<Vec<D>>& y)
    {
        for (std::size_t a = 0; a < y.size(); ++a)
        {
            if (level.fixed[a])
            {
                y[a].setZero();
            }
        }
        const double length = norm(level, y);
        if (length > 0.0)
        {
            for (auto& v : y)
            {
                v /= length;
            }
        }
        if (level.ranks.distributed())
        {
            std::vector<double> component(y.size());
            for (int k = 0; k < D; ++k)
            {
                for (std::size_t a = 0; a < y.size(); ++a)
                {
                    component[a] = y[a][k];
                }
                level.ranks.shareWithGhosts(component);
                for (std::size_t a = 0; a < y.size(); ++a)
                {
                    y[a][k] = component[a];
                }
            }
        }
        return length;
    }

    // y ← y/|y| + 0.1 r/|r|, r uniform in [-½, ½] per component from SplitMix64 (Steele, Lea &
    // Flood 2014) of the step, the particle's global index and the component: the same numbers
    // on every machine, after a restart and on any ranks.
    static void addNoise(const Level& level, std::vector<Vec<D>>& y)
    {
        normalise(level, y);
        std::vector<Vec<D>> r(y.size(), Vec<D>::Zero());
        for (std::size_t a = 0; a < y.size(); ++a)
        {
            for (int k = 0; k < D; ++k)
            {
                const std::uint64_t key = (static_cast<std::uint64_t>(level.step) << 32) ^
                                          (static_cast<std::uint64_t>(level.ranks.global(a)) * D +
                                           static_cast<std::uint64_t>(k));
                r[a][k] = level.fixed[a] ? 0.0
                                         : static_cast<double>(splitMix(key) >> 11) * 0x1.0p-53 - 0.5;
            }
        }
        normalise(level, r);
        for (std::size_t a = 0; a < y.size(); ++a)
        {
            y[a] += 0.1 * r[a];
        }
    }

    static std::uint64_t splitMix(std::uint64_t z)
    {
        z += 0x9E3779B97F4A7C15ULL;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        return z ^ (z >> 31);
    }
};

} // namespace sph
