#pragma once
// When the particle loops use threads. A parallel region costs microseconds to start and
// join; below a few hundred particles the loop itself is cheaper, and many short regions per
// step (the 1D bar takes 10^5 steps) would only add overhead — or, when several runs share the
// cores, stall on descheduled threads. Loops use `#pragma omp parallel ... if (useThreads(n))`.

#include <cstddef>

namespace sph
{

inline constexpr std::size_t minimumParticlesForThreads = 1000;

inline bool useThreads(std::size_t particles)
{
    return particles >= minimumParticlesForThreads;
}

} // namespace sph
