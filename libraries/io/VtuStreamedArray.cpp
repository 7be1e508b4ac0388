#include "io/VtuStreamedArray.hpp"

#include <vtkObjectFactory.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>

namespace sph
{

vtkStandardNewMacro(VtuStreamedArray);

namespace
{

// The item a thread copied out last, of the array with this serial number.
struct ItemCache
{
    std::uint64_t serial = 0; // 0: none
    std::size_t item = 0;
    std::vector<double> values;
};
thread_local ItemCache cache;
std::atomic<std::uint64_t> lastSerial{0};

} // namespace

void VtuStreamedArray::setSource(std::shared_ptr<const VtuStreamedValues> source, int components)
{
    if (!source || components < 1 || source->size() % static_cast<std::size_t>(components) != 0 ||
        (!source->fixedWidth() && (source->offsets.empty() || source->offsets.front() != 0)))
    {
        throw std::logic_error("VtuStreamedArray: a source that is not whole tuples");
    }
    source_ = std::move(source);
    serial_ = ++lastSerial;
    SetNumberOfComponents(components);
    SetNumberOfTuples(static_cast<vtkIdType>(source_->size() / static_cast<std::size_t>(components)));
}

double VtuStreamedArray::GetValue(vtkIdType valueIdx) const
{
    const auto value = static_cast<std::size_t>(valueIdx);
    const VtuStreamedValues& source = *source_;
    if (value >= source.size())
    {
        throw std::out_of_range("VtuStreamedArray: value " + std::to_string(value) + " of " +
                                std::to_string(source.size()));
    }
    if (cache.serial != serial_ || value < source.first(cache.item) ||
        value >= source.first(cache.item + 1))
    {
        // The item that holds it: the last whose first value is not beyond it (items without
        // values share their offset with the next, which upper_bound skips).
        const std::vector<std::size_t>& offsets = source.offsets;
        cache.item = source.fixedWidth()
                         ? value / source.width
                         : static_cast<std::size_t>(std::upper_bound(offsets.begin(), offsets.end(), value) -
                                                    offsets.begin()) - 1;
        cache.values.resize(source.first(cache.item + 1) - source.first(cache.item));
        source.get(cache.item, cache.values.data());
        cache.serial = serial_;
    }
    return cache.values[value - source.first(cache.item)];
}

void VtuStreamedArray::GetTypedTuple(vtkIdType tupleIdx, double* tuple) const
{
    for (int c = 0; c < NumberOfComponents; ++c)
    {
        tuple[c] = GetTypedComponent(tupleIdx, c);
    }
}

double VtuStreamedArray::GetTypedComponent(vtkIdType tupleIdx, int compIdx) const
{
    return GetValue(tupleIdx * NumberOfComponents + compIdx);
}

void materialise(VtuArray& array)
{
    if (!array.streamed)
    {
        return;
    }
    const VtuStreamedValues& source = *array.streamed;
    array.values.resize(source.size());
    for (std::size_t item = 0; item < source.itemCount(); ++item)
    {
        source.get(item, array.values.data() + source.first(item));
    }
    array.streamed.reset();
}

void VtuStreamedArray::readOnly() const
{
    throw std::logic_error("VtuStreamedArray: written into (it streams its source, read-only)");
}

} // namespace sph
