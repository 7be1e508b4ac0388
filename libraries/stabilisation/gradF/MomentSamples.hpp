#pragma once
// gradF's moment points of every particle (`samplePoints moments`, docs/theory/gradF-moments.md):
// made from each particle's reference neighbourhood (MomentPoints.hpp's rule) whenever the
// reference changes, and handed to the force and energy loops in place of the neighbours.

#include "particles/ParticleFields.hpp"
#include "particles/ReferenceConfiguration.hpp"
#include "stabilisation/gradF/MomentPoints.hpp"

#include <cstddef>
#include <limits>
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

    // Updated Lagrangian with states at the points (§M7): each particle's axes A are kept (a
    // restart field, `momentAxes`) and a move turns them with the material (M7.2), so that
    // point q stays the same point; a particle where the rule does not apply samples only its
    // own F (use()'s `alone`).
    void carryStates(ParticleFields<D>& fields)
    {
        carrying_ = true;
        axes_.assign(fields.size(), notYet());
        fields.bind(FieldSpec::tensor("momentAxes",
                                      "the axes of gradF's moment points in the reference "
                                      "(docs/theory/gradF-moments.md §M7) [m]; NaN: none yet")
                        .restart(),
                    axes_, notYet());
    }
    bool carriesStates() const { return carrying_; }
    // A move starts (before the new reference's prepare()): the axes each particle's points
    // are to follow, f_a A_a for the particles given by follow() (the others take the Cholesky
    // axes of their new neighbourhood).
    void startMove(std::size_t n)
    {
        targets_.assign(n, notYet());
        moving_ = true;
    }
    void follow(std::size_t a, const Mat<D>& f)
    {
        if (at(a))
        {
            targets_[a] = f * momentAxes<D>(&points_[a * count]);
        }
    }

    // The points from the reference (invDenominator: 1 / Σ_e W_ae V^r_e of each particle, as
    // gradF's kinematics weighs the neighbours; maxNeighbours: the longest neighbour list).
    void prepare(const ReferenceConfiguration<D>& ref, const std::vector<double>& invDenominator,
                 std::size_t maxNeighbours); // GradFMomentPoints.cpp

    // Whether particle a samples at its moment points (else at its neighbours, §M2).
    bool at(std::size_t a) const { return active_ && weights_[a * count] >= 0.0; }

    // Particle a's sample offsets and weights into xr and w (which kinematics() filled with the
    // neighbours'): its moment points, or, where the rule does not apply, the neighbours left
    // as they are or (alone) the particle only: every point at ξ = 0, ω_0 = 1 (§M7). Returns
    // how many samples there are.
    std::size_t use(std::size_t a, std::size_t neighbours, Vec<D>* xr, double* w,
                    bool alone = false) const
    {
        if (!at(a))
        {
            if (!alone || !active_)
            {
                return neighbours;
            }
            for (std::size_t q = 0; q < count; ++q)
            {
                xr[q] = Vec<D>::Zero();
                w[q] = q == 0 ? 1.0 : 0.0;
            }
            return count;
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
    static Mat<D> notYet() { return Mat<D>::Constant(std::numeric_limits<double>::quiet_NaN()); }
    bool active_ = false;
    bool carrying_ = false;
    bool moving_ = false;          // startMove() until the next prepare()
    std::vector<Mat<D>> axes_;     // carrying_: each particle's axes A (columns)
    std::vector<Mat<D>> targets_;  // f_a A_a of the move under way
    std::vector<Vec<D>> points_;  // count per particle
    std::vector<double> weights_; // count per particle; -1 at point 0: the neighbours (§M2)
};

} // namespace sph
