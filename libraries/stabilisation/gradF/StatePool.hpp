#pragma once
// Records of `width` doubles, each named by an index that stays valid (and its address fixed)
// until it is released: where SampleHistory keeps the states of the stress samples that are
// not in the initial state. Held in blocks, so that growing never copies what is held (a
// std::vector would hold the old and the new array at once, and up to twice the records).
// Released records are handed out again before new ones. Not thread-safe: allocate and
// release from one thread; reading and writing held records from many is fine.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
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
    }
    std::size_t width() const { return width_; }

    Index allocate()
    {
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

    // Records held (handed out and not released).
    std::size_t held() const { return used_ - free_.size(); }

private:
    static constexpr std::size_t blockRecords = 4096;
    std::size_t width_ = 0;
    std::vector<std::unique_ptr<double[]>> blocks_;
    std::vector<Index> free_;
    std::size_t used_ = 0; // records handed out of the blocks so far
};

} // namespace sph
