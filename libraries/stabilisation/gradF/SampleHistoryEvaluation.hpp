#pragma once
// What an evaluation reads of SampleHistory and hands back (SampleHistory.hpp includes this at
// its end): the committed states in rows for a material, the states a commit would make of
// them kept when they differ, and the commit in place.

#include "stabilisation/gradF/SampleHistory.hpp"

namespace sph
{

template <int D>
void SampleHistory<D>::readRows(std::size_t first, std::size_t count, double* out,
                                std::size_t rowLength) const
{
    for (std::size_t c = 0; c < stride_; ++c)
    {
        std::fill(out + c * rowLength, out + (c + 1) * rowLength, initial_[c]);
    }
    if (expandFrom_.empty())
    {
        double state[maxStride];
        for (std::size_t j = 0; j < count; ++j)
        {
            const StatePool::Index slot = slot_[first + j];
            if (slot != StatePool::none)
            {
                codec_->expandHistory(pool_.at(slot), state);
                for (std::size_t c = 0; c < stride_; ++c)
                {
                    out[c * rowLength + j] = state[c];
                }
            }
        }
        return;
    }
    // The samples with a record, a block at a time, then their rows one component at a time: a
    // copy per number without a branch (the component's source is the same for every record),
    // and nothing for a constant component that is the initial state's (already there).
    constexpr std::size_t block = 64;
    const double* records[block];
    std::uint32_t at[block];
    for (std::size_t begin = 0; begin < count; begin += block)
    {
        std::size_t held = 0;
        for (std::size_t j = begin; j < std::min(begin + block, count); ++j)
        {
            const StatePool::Index slot = slot_[first + j];
            if (slot != StatePool::none)
            {
                records[held] = pool_.at(slot);
                at[held] = static_cast<std::uint32_t>(j);
                ++held;
            }
        }
        for (std::size_t c = 0; c < stride_ && held > 0; ++c)
        {
            double* row = out + c * rowLength;
            if (expandFrom_[c] != constant)
            {
                const std::size_t from = expandFrom_[c];
                for (std::size_t k = 0; k < held; ++k)
                {
                    row[at[k]] = records[k][from];
                }
            }
            else if (!sameBits(&expandConstant_[c], &initial_[c], 1))
            {
                for (std::size_t k = 0; k < held; ++k)
                {
                    row[at[k]] = expandConstant_[c];
                }
            }
        }
    }
}

template <int D>
void SampleHistory<D>::keepPending(std::size_t first, std::size_t count, const double* next,
                                   const std::uint8_t* changed)
{
    PendingStates::List& mine = pending_.mine();
    for (std::size_t j = 0; j < count; ++j)
    {
        if (!changed || changed[j])
        {
            keepIfChanged(first + j, next + j * stride_, mine);
        }
    }
}

template <int D> void SampleHistory<D>::commit()
{
    for (const PendingStates::List& p : pending_.lists())
    {
        for (const std::uint32_t slot : p.slots)
        {
            if (slot_[slot] == StatePool::none)
            {
                slot_[slot] = pool_.allocate();
            }
        }
    }
    const std::size_t width = pool_.width();
    const auto lists = static_cast<long>(pending_.lists().size());
#pragma omp parallel for schedule(static, 1) if (lists > 1 && omp_get_max_threads() > 1)
    for (long t = 0; t < lists; ++t)
    {
        const PendingStates::List& p = pending_.lists()[static_cast<std::size_t>(t)];
        for (std::size_t i = 0; i < p.slots.size(); ++i)
        {
            const double* state = p.states.at(static_cast<StatePool::Index>(i));
            double* record = pool_.at(slot_[p.slots[i]]);
            for (std::size_t k = 0; k < width; ++k)
            {
                record[k] = state[k];
            }
        }
    }
    clearPending();
    if (relocationDue())
    {
        std::vector<StatePool::Index> destination;
        relocateInSlotOrder(destination);
    }
}

template <int D>
void SampleHistory<D>::keepIfChanged(std::size_t slot, const double* next,
                                     PendingStates::List& mine)
{
    double state[maxStride];
    compact(next, state);
    const double* committed =
        slot_[slot] == StatePool::none ? initialCompact_.data() : pool_.at(slot_[slot]);
    // (Number by number, with an exit: `state` was just written number by number, and the
    // vector loads of sameBits() waited for those stores.)
    bool same = true;
    for (std::size_t k = 0; k < pool_.width() && same; ++k)
    {
        same = std::bit_cast<std::uint64_t>(state[k]) == std::bit_cast<std::uint64_t>(committed[k]);
    }
    if (!same)
    {
        resizePairArray(mine.slots, mine.slots.size() + 1);
        mine.slots.back() = static_cast<std::uint32_t>(slot); // as NeighbourList's
        std::copy(state, state + pool_.width(), mine.states.at(mine.states.allocate()));
    }
}

template <int D> void SampleHistory<D>::learnExpansion()
{
    expandFrom_.clear();
    const std::size_t width = pool_.width();
    std::vector<double> a(width), b(width), packedA(stride_), packedB(stride_);
    for (std::size_t k = 0; k < width; ++k)
    {
        a[k] = 1.0 + static_cast<double>(k);
        b[k] = 101.0 + static_cast<double>(k);
    }
    codec_->expandHistory(a.data(), packedA.data());
    codec_->expandHistory(b.data(), packedB.data());
    std::vector<std::size_t> from(stride_, constant);
    for (std::size_t c = 0; c < stride_; ++c)
    {
        if (packedA[c] == packedB[c])
        {
            continue; // a constant
        }
        const double k = packedA[c] - 1.0;
        if (!(k >= 0.0 && k < static_cast<double>(width) &&
              packedB[c] == b[static_cast<std::size_t>(k)] &&
              packedA[c] == a[static_cast<std::size_t>(k)]))
        {
            return; // not a copy: the codec expands each record
        }
        from[c] = static_cast<std::size_t>(k);
    }
    expandFrom_ = std::move(from);
    expandConstant_ = packedA;
}

} // namespace sph
