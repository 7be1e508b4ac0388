#pragma once
// What an evaluation reads of SampleHistory and hands back (SampleHistory.hpp includes this at
// its end): the committed states in rows for a material, the states a commit would make of
// them kept when they differ, and the commit in place.

#include "stabilisation/gradF/SampleHistory.hpp"

namespace sph
{

template <int D>
const double* SampleHistory<D>::fromOneRun(std::size_t first, std::size_t count) const
{
    const StatePool::Index head = count > 0 ? slot_[first] : StatePool::none;
    if (expandFrom_.empty() || !isRecord(head) ||
        !isRecord(head + static_cast<StatePool::Index>(count - 1)))
    {
        return nullptr;
    }
    bool sideBySide = true;
    for (std::size_t j = 1; j < count; ++j)
    {
        sideBySide &= slot_[first + j] == head + static_cast<StatePool::Index>(j);
    }
    return sideBySide ? pool_.run(head, count) : nullptr;
}

template <int D>
void SampleHistory<D>::readRows(std::size_t first, std::size_t count, double* out,
                                std::size_t rowLength, std::size_t padTo) const
{
    // The rows past count hold the initial state; so do all of them unless each entry is
    // written below (from one run of records).
    const double* run = fromOneRun(first, count);
    const std::size_t written = run ? count : 0;
    for (std::size_t c = 0; c < stride_; ++c)
    {
        std::fill(out + c * rowLength + written, out + c * rowLength + padTo, initial_[c]);
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
    // Every sample with a record, the records side by side in slot order (a flowing particle's,
    // once commit() or follow() relocated them): each row a strided copy of one component.
    if (run)
    {
        const std::size_t width = pool_.width();
        for (std::size_t c = 0; c < stride_; ++c)
        {
            double* row = out + c * rowLength;
            if (expandFrom_[c] != constant)
            {
                const double* from = run + expandFrom_[c];
                for (std::size_t j = 0; j < count; ++j)
                {
                    row[j] = from[j * width];
                }
            }
            else
            {
                std::fill(row, row + count, expandConstant_[c]);
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

template <int D> bool SampleHistory<D>::compactsExactly(const double* packed) const
{
    std::uint64_t difference = 0;
    for (const CompactCheck& check : compactChecks_)
    {
        const double expected = check.sameAs == constant ? check.value : packed[check.sameAs];
        difference |= std::bit_cast<std::uint64_t>(expected) ^
                      std::bit_cast<std::uint64_t>(packed[check.at]);
    }
    return difference == 0;
}

template <int D>
void SampleHistory<D>::keepPending(std::size_t first, std::size_t count, const double* next,
                                   const std::uint8_t* changed)
{
    PendingStates::List& mine = pending_.mine();
    withRecordWidth([&](auto width)
                    { keepChanged<decltype(width)::value>(first, count, next, changed, mine); });
}

template <int D>
template <class F>
void SampleHistory<D>::withRecordWidth(F&& f) const
{
    switch (pool_.width())
    {
    case 5: f(std::integral_constant<std::size_t, 5>{}); break;
    case 6: f(std::integral_constant<std::size_t, 6>{}); break;
    case 7: f(std::integral_constant<std::size_t, 7>{}); break;
    case 8: f(std::integral_constant<std::size_t, 8>{}); break;
    default: f(std::integral_constant<std::size_t, 0>{}); break;
    }
}

template <int D>
template <std::size_t W>
void SampleHistory<D>::keepChanged(std::size_t first, std::size_t count, const double* next,
                                   const std::uint8_t* changed, PendingStates::List& mine)
{
    const std::size_t width = W > 0 ? W : pool_.width();
    // Room for every sample's slot at once (each kept one then a push without a reallocation;
    // grown by 1/16 beyond, as resizePairArray() grows a pair array).
    const std::size_t room = mine.slots.size() + count;
    if (mine.slots.capacity() < room)
    {
        mine.slots.reserve(room + room / 16);
    }
    // Compact number k of a packed state is its compactFrom_[k] (where the codec's compaction
    // is a copy): compared and kept straight from the packed state. (A compact copy built
    // first, with vector stores, and read back number by number stalled on each read.)
    std::size_t from[W > 0 ? W : maxStride];
    const bool byCopies = !compactFrom_.empty();
    for (std::size_t k = 0; byCopies && k < width; ++k)
    {
        from[k] = compactFrom_[k];
    }
    for (std::size_t j = 0; j < count; ++j)
    {
        if (changed && !changed[j])
        {
            continue;
        }
        const double* packed = next + j * stride_;
        double compacted[W > 0 ? W : maxStride];
        const double* source = packed;
        const std::size_t* at = from;
        if (!(byCopies && compactsExactly(packed)))
        {
            compact(packed, compacted); // the codec's (which stops a state it cannot keep)
            source = compacted;
            at = identity_.data();
        }
        // A sample that has a record and that the material says changed (it flowed: its α
        // grew) is kept without comparing: reading its record again here waited on the cache
        // each time, and where the state did come out equal the commit rewrites the same
        // numbers. A sample without one keeps none while it is in the initial state.
        const std::size_t slot = first + j;
        const bool record = slot_[slot] != StatePool::none;
        bool keep = record && changed;
        if (!keep)
        {
            const double* committed = record ? pool_.at(slot_[slot]) : initialCompact_.data();
            std::uint64_t difference = 0;
            for (std::size_t k = 0; k < width; ++k)
            {
                difference |= std::bit_cast<std::uint64_t>(source[at[k]]) ^
                              std::bit_cast<std::uint64_t>(committed[k]);
            }
            keep = difference != 0;
        }
        if (keep)
        {
            mine.slots.push_back(static_cast<std::uint32_t>(slot)); // as NeighbourList's
            double* pending = mine.states.at(mine.states.allocate());
            for (std::size_t k = 0; k < width; ++k)
            {
                pending[k] = source[at[k]];
            }
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
        withRecordWidth(
            [&](auto fixed)
            {
                constexpr std::size_t W = decltype(fixed)::value;
                const std::size_t n = W > 0 ? W : width;
                for (std::size_t i = 0; i < p.slots.size(); ++i)
                {
                    const double* state = p.states.at(static_cast<StatePool::Index>(i));
                    double* record = pool_.at(slot_[p.slots[i]]);
                    for (std::size_t k = 0; k < n; ++k)
                    {
                        record[k] = state[k];
                    }
                }
            });
    }
    clearPending();
    if (relocationDue())
    {
        std::vector<StatePool::Index> destination;
        relocateInSlotOrder(destination);
    }
}

template <int D> void SampleHistory<D>::learnExpansion()
{
    identity_.resize(pool_.width());
    for (std::size_t k = 0; k < identity_.size(); ++k)
    {
        identity_[k] = k;
    }
    expandFrom_.clear();
    compactFrom_.clear();
    compactChecks_.clear();
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
    // The inverse, where every compact number is copied to some component.
    std::vector<std::size_t> compactFrom(width, constant);
    for (std::size_t c = 0; c < stride_; ++c)
    {
        if (from[c] != constant && compactFrom[from[c]] == constant)
        {
            compactFrom[from[c]] = c;
        }
    }
    compactFrom_.clear();
    compactChecks_.clear();
    if (std::find(compactFrom.begin(), compactFrom.end(), constant) == compactFrom.end())
    {
        for (std::size_t c = 0; c < stride_; ++c)
        {
            if (from[c] == constant)
            {
                compactChecks_.push_back({c, constant, packedA[c]});
            }
            else if (compactFrom[from[c]] != c)
            {
                compactChecks_.push_back({c, compactFrom[from[c]], 0.0});
            }
        }
        compactFrom_ = std::move(compactFrom);
    }
    expandFrom_ = std::move(from);
    expandConstant_ = packedA;
}

} // namespace sph
