#pragma once
// Records of `width` doubles, each named by an index that stays valid (and its address fixed)
// until it is released: where SampleHistory keeps the states of the stress samples that are
// not in the initial state. Held in blocks, so that growing never copies what is held (a
// std::vector would hold the old and the new array at once, and up to twice the records).
// Released records are handed out again before new ones. Not thread-safe: allocate and
// release from one thread; reading and writing held records from many is fine.
//
// Why relocate(): the owner reads its records in the order of its own slots, every step. Records
// handed out from the free list land wherever earlier ones were released, so after enough
// turnover that order is a random walk over the blocks, and each read is a cache miss (`perf`:
// 9 % of the column collapse's step at 2.5 mm in one instruction). relocate() puts the held
// records back in the owner's order, in place.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace sph
{

class StatePool
{
public:
    using Index = std::uint32_t;
    // No record (the largest index is never handed out).
    static constexpr Index none = std::numeric_limits<Index>::max();

    // Drops every record; records are then `width` doubles.
    void reset(std::size_t width)
    {
        width_ = width;
        blocks_.clear();
        free_.clear();
        free_.shrink_to_fit();
        used_ = 0;
        allocatedSinceOrdered_ = 0;
    }
    std::size_t width() const { return width_; }
    // Every record released at once; the blocks stay for the records to come, which are handed
    // out from index 0 again (a list refilled every step holds its memory, and never copies).
    void releaseAll()
    {
        free_.clear();
        used_ = 0;
        allocatedSinceOrdered_ = 0;
    }

    Index allocate()
    {
        ++allocatedSinceOrdered_;
        if (!free_.empty())
        {
            const Index index = free_.back();
            free_.pop_back();
            return index;
        }
        if (used_ == blocks_.size() * blockRecords)
        {
            if (used_ >= static_cast<std::size_t>(none) - blockRecords)
            {
                throw std::length_error("StatePool: more than 2^32 - 1 records");
            }
            blocks_.push_back(std::make_unique<double[]>(blockRecords * width_));
        }
        return static_cast<Index>(used_++);
    }
    void release(Index index) { free_.push_back(index); }

    double* at(Index index) { return &blocks_[index / blockRecords][(index % blockRecords) * width_]; }
    const double* at(Index index) const
    {
        return &blocks_[index / blockRecords][(index % blockRecords) * width_];
    }

    // Records index .. index + n − 1, where they lie side by side (in one block): the first's
    // address; else null.
    const double* run(Index index, std::size_t n) const
    {
        return index % blockRecords + n <= blockRecords ? at(index) : nullptr;
    }

    // Records held (handed out and not released).
    std::size_t held() const { return used_ - free_.size(); }
    // Indices handed out so far (held or released): 0 .. extent() − 1.
    std::size_t extent() const { return used_; }
    // Records handed out since the last reset() or relocate(): how far the order has decayed.
    std::size_t allocatedSinceOrdered() const { return allocatedSinceOrdered_; }

    // Moves every held record to a new index, in place: record i (of the used_ ever handed
    // out) goes to destination[i], or is dropped if destination[i] == none (a released one).
    // The destinations of the held records must be 0 .. held() − 1, each once; they become the
    // records 0 .. held() − 1, the free list empties and the blocks no longer needed are freed.
    // `destination` is overwritten (it serves as the cycle marker).
    void relocate(std::vector<Index>& destination)
    {
        if (destination.size() != used_)
        {
            throw std::logic_error("StatePool::relocate: " + std::to_string(destination.size()) +
                                   " destinations for " + std::to_string(used_) + " records");
        }
        const std::size_t kept = held();
        std::vector<double> carried(width_);
        for (std::size_t i = 0; i < used_; ++i)
        {
            // Follow the cycle through i: each swap puts one record at its destination.
            while (destination[i] != none && destination[i] != i)
            {
                const Index to = destination[i];
                if (to >= kept)
                {
                    throw std::logic_error("StatePool::relocate: a destination beyond the records held");
                }
                double* here = at(static_cast<Index>(i));
                double* there = at(to);
                std::copy(there, there + width_, carried.begin());
                std::copy(here, here + width_, there);
                std::copy(carried.begin(), carried.end(), here);
                std::swap(destination[i], destination[to]);
                destination[to] = to;
            }
        }
        used_ = kept;
        free_.clear();
        free_.shrink_to_fit();
        blocks_.resize((kept + blockRecords - 1) / blockRecords);
        allocatedSinceOrdered_ = 0;
    }

private:
    static constexpr std::size_t blockRecords = 4096;
    std::size_t width_ = 0;
    std::vector<std::unique_ptr<double[]>> blocks_;
    std::vector<Index> free_;
    std::size_t used_ = 0; // records handed out of the blocks so far
    std::size_t allocatedSinceOrdered_ = 0;
};

} // namespace sph
