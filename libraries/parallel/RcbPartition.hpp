#pragma once
// Which rank owns each particle: recursive coordinate bisection (Zoltan's RCB) of the particles
// every rank holds, cut so that each rank gets the same count to within one particle (issue 14,
// partition at start and rebalancing). RCB gives each rank a box, so the ghost layer a rank
// needs is the particles within the interaction range of its box.
//
// Deterministic: the same particles in the same order on the same ranks give the same owners.
// Zoltan is not visible here (it is linked privately), nor is MPI.

#include "parallel/Communicator.hpp"
#include "particles/Types.hpp"

#include <cstdint>
#include <vector>

namespace sph
{

// The new owner rank of each of this rank's particles (positions x, global ids id, both of
// this rank's particles only). Collective: every rank calls it.
template <int D>
std::vector<int> rcbOwners(const Communicator& comm, const std::vector<Vec<D>>& x,
                           const std::vector<std::uint64_t>& id);

} // namespace sph
