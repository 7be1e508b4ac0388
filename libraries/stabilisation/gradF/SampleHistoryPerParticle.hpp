#pragma once
// SampleHistory laid out per particle (SampleHistory.hpp includes this at its end; gradF's moment
// points in updated Lagrangian form, docs/theory/gradF-moments.md §M7): follow() keeps each
// particle's samples whatever its neighbours, and lays a particle without any out from its own
// state.

#include "stabilisation/gradF/SampleHistory.hpp"

namespace sph
{

// Each particle keeps its perParticle_ samples from one layout to the next (slot q its point q,
// §M7); a particle without any yet (a new run; a particle with no history before) is laid out
// for the first time, its samples starting from its own state.
template <int D>
void SampleHistory<D>::layOutPerParticle(std::size_t n, const std::vector<int>& body,
                                         const std::vector<const Material<D>*>& materials)
{
    bool same = true;
    for (std::size_t a = 0; a < n && same; ++a)
    {
        same = entries(a) == perParticle_;
    }
    if (!same)
    {
        std::vector<std::size_t> offsets(n + 1, 0);
        for (std::size_t a = 0; a < n; ++a)
        {
            offsets[a + 1] = offsets[a] + perParticle_;
        }
        std::vector<StatePool::Index> slots(offsets.back(), StatePool::none);
        std::vector<int> labels(offsets.back());
        std::vector<double> weights(weighted_ ? offsets.back() : 0,
                                    std::numeric_limits<double>::quiet_NaN());
        std::array<double, maxStride> owner{};
        for (std::size_t a = 0; a < n; ++a)
        {
            for (std::size_t q = 0; q < perParticle_; ++q)
            {
                labels[offsets[a] + q] = static_cast<int>(q);
            }
            if (entries(a) == perParticle_)
            {
                std::copy(&slot_[offsets_[a]], &slot_[offsets_[a + 1]], &slots[offsets[a]]);
                if (weighted_)
                {
                    std::copy(&weights_[offsets_[a]], &weights_[offsets_[a + 1]],
                              &weights[offsets[a]]);
                }
                continue;
            }
            if (entries(a) != 0)
            {
                throw std::runtime_error(
                    "momentPointHistory: particle " + std::to_string(a) + " has " +
                    std::to_string(entries(a)) + " samples, not " + std::to_string(perParticle_) +
                    " (written with other settings than this run's)");
            }
            const Material<D>* material = materials[static_cast<std::size_t>(body[a])];
            if (material->historyComponents() == 0)
            {
                continue;
            }
            material->packHistory(a, owner.data());
            if (isInitial(owner.data()))
            {
                continue;
            }
            for (std::size_t q = 0; q < perParticle_; ++q)
            {
                slots[offsets[a] + q] = pool_.allocate();
                compact(owner.data(), pool_.at(slots[offsets[a] + q]));
            }
        }
        offsets_.swap(offsets);
        slot_.swap(slots);
        neighbours_.swap(labels);
        weights_.swap(weights);
        std::vector<StatePool::Index> buffer;
        relocateInSlotOrder(buffer);
    }
    else if (relocationDue())
    {
        std::vector<StatePool::Index> buffer;
        relocateInSlotOrder(buffer);
    }
    clearPending();
    current_ = true;
}

} // namespace sph
