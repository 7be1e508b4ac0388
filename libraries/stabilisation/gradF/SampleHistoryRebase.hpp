#pragma once
// What a move of the reference does to SampleHistory's states (SampleHistory.hpp includes this
// at its end; docs/theory/gradF-plastic.md §G4): every sample of a particle with history gets a
// record, rebase() re-expresses the records in place so that each sample's be is kept, and
// setState() sets one (an opened particle's samples, §G22).

#include "stabilisation/gradF/SampleHistory.hpp"

namespace sph
{

template <int D>
template <class Materials>
void SampleHistory<D>::storeEveryState(const std::vector<int>& body, const Materials& materials)
{
    for (std::size_t a = 0; a + 1 < offsets_.size(); ++a)
    {
        const auto* material = materials[static_cast<std::size_t>(body[a])];
        if (!material || material->historyComponents() == 0)
        {
            continue;
        }
        for (std::size_t k = offsets_[a]; k < offsets_[a + 1]; ++k)
        {
            if (slot_[k] == StatePool::none)
            {
                slot_[k] = pool_.allocate();
                compact(initial_.data(), pool_.at(slot_[k]));
            }
        }
    }
}

template <int D>
void SampleHistory<D>::rebase(std::size_t first, std::size_t count, const Material<D>& material,
                              const Mat<D>* from, const Mat<D>& to, double* buffer)
{
    for (std::size_t j = 0; j < count; ++j)
    {
        if (!isRecord(slot_[first + j]))
        {
            throw std::logic_error("SampleHistory: rebase() of a state without a record");
        }
        readSlot(first + j, buffer + j * stride_);
    }
    material.rebaseHistories(buffer, stride_, count, from, to);
    for (std::size_t j = 0; j < count; ++j)
    {
        compact(buffer + j * stride_, pool_.at(slot_[first + j]));
    }
}

template <int D> void SampleHistory<D>::setState(std::size_t k, const double* packed)
{
    if (!isRecord(slot_[k]))
    {
        throw std::logic_error("SampleHistory: setState() of a state without a record");
    }
    compact(packed, pool_.at(slot_[k]));
}

} // namespace sph
