#pragma once
// gradF's moment points of every particle (`samplePoints moments`, docs/theory/gradF-moments.md):
// made from each particle's reference neighbourhood (MomentPoints.hpp's rule) whenever the
// reference changes, and handed to the force and energy loops in place of the neighbours.

#include "particles/ReferenceConfiguration.hpp"
#include "stabilisation/gradF/MomentPoints.hpp"

#include <cstddef>
#include <vector>

namespace sph
{

template <int D>
class MomentSamples
{
public:
    static constexpr std::size_t count = MomentPoints<D>::count;

    bool active() const { return active_; }
    void activate(bool on) { active_ = on; }

    // The points from the reference (invDenominator: 1 / Σ_e W_ae V^r_e of each particle, as
    // gradF's kinematics weighs the neighbours; maxNeighbours: the longest neighbour list).
    void prepare(const ReferenceConfiguration<D>& ref, const std::vector<double>& invDenominator,
                 std::size_t maxNeighbours); // GradFMomentPoints.cpp

    // Whether particle a samples at its moment points (else at its neighbours, §M2).
    bool at(std::size_t a) const { return active_ && weights_[a * count] >= 0.0; }

    // Particle a's sample offsets and weights into xr and w (which kinematics() filled with the
    // neighbours'): its moment points, or the neighbours left as they are. Returns how many
    // samples there are.
    std::size_t use(std::size_t a, std::size_t neighbours, Vec<D>* xr, double* w) const
    {
        if (!at(a))
        {
            return neighbours;
        }
        const std::size_t first = a * count;
        for (std::size_t q = 0; q < count; ++q)
        {
            xr[q] = points_[first + q];
            w[q] = weights_[first + q];
        }
        return count;
    }

    // How many particles from a (below end) in a row sample at their moment points, at most
    // `most`, at least 1: those whose samples a material can evaluate together.
    std::size_t run(std::size_t a, std::size_t end, std::size_t most) const
    {
        std::size_t n = 0;
        while (n < most && a + n < end && at(a + n))
        {
            ++n;
        }
        return n > 0 ? n : 1;
    }

private:
    bool active_ = false;
    std::vector<Vec<D>> points_;  // count per particle
    std::vector<double> weights_; // count per particle; -1 at point 0: the neighbours (§M2)
};

} // namespace sph
