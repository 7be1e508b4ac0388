#pragma once
// The states a force evaluation of gradF's samples found a commit would make, kept until the
// commit (SampleHistory): per evaluating thread, the slots whose state changes and their states
// in compact form. They are held in StatePool blocks, grown without a copy and refilled every
// step in the memory they already hold. Only the last evaluation's states are committed: each
// evaluation starts with clear(), and the operator probe's evaluations set the level's states
// aside and put them back.

#include "stabilisation/gradF/StatePool.hpp"

#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace sph
{

class PendingStates
{
public:
    // One thread's states: state i (states.at(i)) is that of slot slots[i].
    struct List
    {
        std::vector<std::uint32_t> slots;
        StatePool states;
    };

    // An evaluation starts, with states of `width` numbers: what the last one kept is dropped,
    // and each thread that may evaluate gets a list.
    void clear(std::size_t width)
    {
        lists_.resize(static_cast<std::size_t>(std::max(1, omp_get_max_threads())));
        for (List& list : lists_)
        {
            list.slots.clear();
            if (list.states.width() == width)
            {
                list.states.releaseAll();
            }
            else
            {
                list.states.reset(width);
            }
        }
    }
    // The calling thread's list, after clear().
    List& mine()
    {
        const auto thread = static_cast<std::size_t>(omp_get_thread_num());
        if (thread >= lists_.size())
        {
            throw std::logic_error("PendingStates: a thread's list asked for before clear()");
        }
        return lists_[thread];
    }
    const std::vector<List>& lists() const { return lists_; }

    // The last evaluation's states set aside while other evaluations come, and put back.
    void setAside() { lists_.swap(aside_); }
    void restore()
    {
        lists_.swap(aside_);
        aside_.clear(); // the other evaluations' states: no memory held until they come again
    }

private:
    std::vector<List> lists_;
    std::vector<List> aside_;
};

} // namespace sph
