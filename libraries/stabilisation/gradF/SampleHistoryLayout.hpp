#pragma once
// SampleHistory's layout along the neighbour list (SampleHistory.hpp includes this at its end;
// per particle: SampleHistoryPerParticle.hpp):
// follow() moves each state to its pair's new slot when the list changes, new pairs take their
// owner's or their neighbour's state, the pairs that leave are set aside with their weights, and
// the records are put back in slot order once they have scattered.

#include "stabilisation/gradF/SampleHistory.hpp"

namespace sph
{

template <int D>
void SampleHistory<D>::follow(const NeighbourList& list, const std::vector<int>& body,
                              const std::vector<const Material<D>*>& materials,
                              const std::vector<int>* globalId, const std::vector<Mat<D>>* Fr)
{
    if (current_ || !active())
    {
        return;
    }
    const std::size_t n = list.particleCount();
    if (offsets_.size() != n + 1)
    {
        throw std::logic_error("SampleHistory: the states are of " + std::to_string(size()) +
                               " particles, the list of " + std::to_string(n));
    }
    if (perParticle_ > 0)
    {
        layOutPerParticle(n, body, materials);
        return;
    }
    const auto global = [globalId](std::size_t b) {
        return globalId ? (*globalId)[b] : static_cast<int>(b);
    };
    // The new slots name the records of the kept pairs (whose old slots are marked
    // `moved`), or say where a new pair's state comes from. In a buffer of this move only:
    // held between moves it cost 4 B per pair (8 more with weights) for the whole run, where
    // its allocation costs a move a small fraction of its time.
    std::vector<StatePool::Index> remapped(list.pairCount());
    std::vector<double> remappedWeights(weighted_ ? list.pairCount() : 0);
    std::vector<std::uint8_t> hasNew(n, 0);
    // Whether some of a's old pairs leave the list (their records are released below): most
    // particles keep every pair from one move to the next, and a scan of every old slot for
    // the records left behind cost 5 % of a step of the rings in UL gradF.
    std::vector<std::uint8_t> hasLeaving(n, 0);
#pragma omp parallel if (useThreads(n))
    {
        std::array<double, maxStride> owner{};
#pragma omp for schedule(static)
        for (std::size_t a = 0; a < n; ++a)
        {
            const Material<D>* material = materials[static_cast<std::size_t>(body[a])];
            if (material->historyComponents() == 0)
            {
                std::fill(&remapped[list.begin(a)], &remapped[list.begin(a)] + list.count(a),
                          StatePool::none); // never read
                continue;
            }
            std::size_t old = offsets_[a];
            const std::size_t oldEnd = offsets_[a + 1];
            // The common case: a's neighbours are those of the last layout, in the same order.
            // Each pair keeps its slot's state (what the merge below finds for it), by copies.
            // (Loops over plain arrays, which vectorise.)
            const std::size_t first = list.begin(a);
            const std::size_t count = list.count(a);
            if (oldEnd - old == count)
            {
                const int* oldIds = &neighbours_[old];
                const auto* newLocal = &list.indices[first];
                bool same = true;
                if (globalId)
                {
                    for (std::size_t j = 0; j < count; ++j)
                    {
                        same &= oldIds[j] == (*globalId)[newLocal[j]];
                    }
                }
                else
                {
                    for (std::size_t j = 0; j < count; ++j)
                    {
                        same &= oldIds[j] == static_cast<int>(newLocal[j]);
                    }
                }
                if (same)
                {
                    StatePool::Index* from = &slot_[old];
                    StatePool::Index* to = &remapped[first];
                    for (std::size_t j = 0; j < count; ++j)
                    {
                        to[j] = from[j];
                    }
                    std::fill(from, from + count, moved);
                    if (weighted_)
                    {
                        std::copy(&weights_[old], &weights_[old] + count, &remappedWeights[first]);
                    }
                    continue;
                }
            }
            material->packHistory(a, owner.data());
            const bool ownerInitial = isInitial(owner.data());
            std::size_t keptPairs = 0;
            for (std::size_t k = list.begin(a); k < list.end(a); ++k)
            {
                // Both: a itself first, then its neighbours in increasing global index
                // (local particles are in increasing global index).
                const int b = global(list.indices[k]);
                const bool self = k == list.begin(a);
                while (!self && old < oldEnd && (old == offsets_[a] || neighbours_[old] < b))
                {
                    ++old;
                }
                const bool kept = old < oldEnd && neighbours_[old] == b;
                const std::size_t local = list.indices[k];
                if (weighted_)
                {
                    const bool firstLayout = oldEnd == offsets_[a];
                    remappedWeights[k] = kept          ? weights_[old]
                                          : firstLayout ? std::numeric_limits<double>::quiet_NaN()
                                                        : 0.0;
                }
                if (kept)
                {
                    remapped[k] = slot_[old];
                    slot_[old] = moved;
                    ++keptPairs;
                }
                // (A particle with no states yet is being laid out for the first time:
                // its samples start virgin, as its own state does.)
                else if (!self && Fr && oldEnd > offsets_[a] &&
                         materials[static_cast<std::size_t>(body[local])] == material)
                {
                    remapped[k] = fromNeighbour;
                    hasNew[a] = 1;
                }
                else
                {
                    remapped[k] = ownerInitial ? StatePool::none : fromOwner;
                    hasNew[a] = !ownerInitial || hasNew[a];
                }
            }
            hasLeaving[a] = keptPairs < oldEnd - offsets_[a] ? 1 : 0;
        }
    }
    if (weighted_)
    {
        setAsideLeaving(body, materials);
        weights_.swap(remappedWeights);
    }
    // The records of the pairs that left (kept ones are marked `moved`), in slot order.
    for (std::size_t a = 0; a < n; ++a)
    {
        if (!hasLeaving[a])
        {
            continue;
        }
        for (std::size_t old = offsets_[a]; old < offsets_[a + 1]; ++old)
        {
            if (isRecord(slot_[old]))
            {
                pool_.release(slot_[old]);
            }
        }
    }
    slot_.swap(remapped);
    offsets_.assign(list.offsets.begin(), list.offsets.end());
    resizePairArray(neighbours_, list.indices.size());
#pragma omp parallel for schedule(static) if (useThreads(n))
    for (std::size_t k = 0; k < neighbours_.size(); ++k)
    {
        neighbours_[k] = global(list.indices[k]);
    }
    storeNewStates(list, body, materials, hasNew, Fr);
    if (relocationDue())
    {
        relocateInSlotOrder(remapped);
    }
    clearPending();
    current_ = true;
}

template <int D>
void SampleHistory<D>::assign(const std::vector<std::size_t>& counts, std::vector<double> values)
{
    offsets_.assign(counts.size() + 1, 0);
    for (std::size_t a = 0; a < counts.size(); ++a)
    {
        offsets_[a + 1] = offsets_[a] + counts[a];
    }
    const std::size_t pairs = offsets_.back();
    if (values.size() != pairs * width())
    {
        throw std::logic_error("SampleHistory: " + std::to_string(values.size()) +
                               " numbers for " + std::to_string(pairs) + " samples");
    }
    pool_.reset(pool_.width());
    neighbours_.assign(pairs, 0);
    slot_.assign(pairs, StatePool::none);
    weights_.resize(weighted_ ? pairs : 0);
    for (std::size_t k = 0; k < pairs; ++k)
    {
        const double* in = &values[k * width()];
        if (!(in[0] >= 0.0 && in[0] <= std::numeric_limits<int>::max() &&
              in[0] == std::floor(in[0])))
        {
            throw std::runtime_error("sampleHistory: a neighbour index " +
                                     std::to_string(in[0]) + " that is not a particle's");
        }
        neighbours_[k] = static_cast<int>(in[0]);
        if (!isInitial(in + 1))
        {
            slot_[k] = pool_.allocate();
            compact(in + 1, pool_.at(slot_[k]));
        }
        if (weighted_)
        {
            weights_[k] = in[1 + stride_];
        }
    }
    clearPending();
    current_ = false;
}

template <int D> bool SampleHistory<D>::recordsInSlotOrder() const
{
    bool first = true;
    StatePool::Index last = 0;
    for (const StatePool::Index record : slot_)
    {
        if (isRecord(record))
        {
            if (!first && record <= last)
            {
                return false;
            }
            last = record;
            first = false;
        }
    }
    return true;
}

template <int D>
void SampleHistory<D>::relocateInSlotOrder(std::vector<StatePool::Index>& destination)
{
    resizePairArray(destination, pool_.extent());
    std::fill(destination.begin(), destination.end(), StatePool::none);
    StatePool::Index next = 0;
    for (StatePool::Index& record : slot_)
    {
        if (isRecord(record))
        {
            destination[record] = next;
            record = next++;
        }
    }
    pool_.relocate(destination);
}

template <int D>
void SampleHistory<D>::storeNewStates(const NeighbourList& list, const std::vector<int>& body,
                                      const std::vector<const Material<D>*>& materials,
                                      const std::vector<std::uint8_t>& hasNew,
                                      const std::vector<Mat<D>>* Fr)
{
    std::array<double, maxStride> state{};
    for (std::size_t a = 0; a < hasNew.size(); ++a)
    {
        if (!hasNew[a])
        {
            continue;
        }
        const Material<D>* material = materials[static_cast<std::size_t>(body[a])];
        for (std::size_t k = list.begin(a); k < list.end(a); ++k)
        {
            if (slot_[k] == fromOwner)
            {
                material->packHistory(a, state.data());
            }
            else if (slot_[k] == fromNeighbour)
            {
                const std::size_t local = list.indices[k];
                material->packHistory(local, state.data());
                material->rebaseHistory(state.data(), (*Fr)[local], (*Fr)[a]);
            }
            else
            {
                continue;
            }
            slot_[k] = StatePool::none;
            if (!isInitial(state.data()))
            {
                slot_[k] = pool_.allocate();
                compact(state.data(), pool_.at(slot_[k]));
            }
        }
    }
}

template <int D>
void SampleHistory<D>::setAsideLeaving(const std::vector<int>& body,
                                       const std::vector<const Material<D>*>& materials)
{
    const std::size_t n = offsets_.size() - 1;
    leavingOffsets_.assign(n + 1, 0);
    leavingWeights_.clear();
    leavingStates_.clear();
    for (std::size_t a = 0; a < n; ++a)
    {
        if (materials[static_cast<std::size_t>(body[a])]->historyComponents() > 0)
        {
            for (std::size_t old = offsets_[a]; old < offsets_[a + 1]; ++old)
            {
                if (slot_[old] != moved)
                {
                    leavingWeights_.push_back(weights_[old]);
                    leavingStates_.resize(leavingStates_.size() + stride_);
                    readSlot(old, &leavingStates_[leavingStates_.size() - stride_]);
                }
            }
        }
        leavingOffsets_[a + 1] = leavingWeights_.size();
    }
}

} // namespace sph
