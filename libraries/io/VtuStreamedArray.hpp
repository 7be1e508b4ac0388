#pragma once
// A VTK data array whose values are not in memory: VTK's XML writer reads them in order, value
// by value (its path for arrays that are not one contiguous block), and this array asks its
// source for one item at a time (VtuStreamedValues: gradF's samples of one particle), so that
// writing a large field-data array costs one item's values instead of a copy of all of them.
// VTK also reads it from several threads at once (the range it writes in the file's header),
// each in order through its own chunk: each thread keeps the item it read last, so the source's
// get() must be safe to call concurrently (a const read). Read-only: VTK sizes it once, nothing
// writes into it.

#include "io/VtuFile.hpp"

#include <vtkGenericDataArray.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace sph
{

class VtuStreamedArray : public vtkGenericDataArray<VtuStreamedArray, double>
{
    using GenericDataArrayType = vtkGenericDataArray<VtuStreamedArray, double>;

public:
    vtkTemplateTypeMacro(VtuStreamedArray, GenericDataArrayType);
    static VtuStreamedArray* New();

    // Streams `source` as tuples of `components` values.
    void setSource(std::shared_ptr<const VtuStreamedValues> source, int components);

    double GetValue(vtkIdType valueIdx) const;
    void GetTypedTuple(vtkIdType tupleIdx, double* tuple) const;
    double GetTypedComponent(vtkIdType tupleIdx, int compIdx) const;
    // Nothing writes into a streamed array (VTK's writer only reads).
    void SetValue(vtkIdType, double) { readOnly(); }
    void SetTypedTuple(vtkIdType, const double*) { readOnly(); }
    void SetTypedComponent(vtkIdType, int, double) { readOnly(); }

protected:
    VtuStreamedArray() = default;
    // No storage to allocate: the size is the source's.
    bool AllocateTuples(vtkIdType) { return true; }
    bool ReallocateTuples(vtkIdType) { return true; }

private:
    friend class vtkGenericDataArray<VtuStreamedArray, double>;
    void readOnly() const;

    std::shared_ptr<const VtuStreamedValues> source_;
    // Names this array's source in the threads' caches (an address could be reused).
    std::uint64_t serial_ = 0;
};

} // namespace sph
