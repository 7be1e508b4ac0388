#include "solver/StateFile.hpp"

#include "core/InputError.hpp"

#include <array>

namespace sph
{

namespace
{

// Components of a field as displayed: vectors in 3D, tensors 3×3.
int displayComponents(FieldKind kind)
{
    return kind == FieldKind::vector ? 3 : kind == FieldKind::tensor ? 9 : 1;
}

// Index of native component c (of a D-vector or D×D tensor) in the display layout.
template <int D>
int displayIndex(FieldKind kind, int c)
{
    if (kind == FieldKind::tensor)
    {
        return 3 * (c / D) + c % D;
    }
    return c;
}

template <int D>
VtuArray arrayOf(const typename ParticleFields<D>::Field& field, std::size_t n)
{
    const FieldSpec& spec = field.spec;
    const int native = field.components();
    const bool display = spec.isDisplay();
    const int shown = display ? displayComponents(spec.kind()) : native;
    std::vector<double> padding(static_cast<std::size_t>(shown), 0.0);
    if (display && spec.kind() == FieldKind::tensor && spec.tensorPadding() == TensorPadding::identity)
    {
        padding[0] = padding[4] = padding[8] = 1.0;
    }
    VtuArray array;
    array.components = shown;
    array.integer = spec.kind() == FieldKind::integer;
    array.values.resize(n * static_cast<std::size_t>(shown));
    std::array<double, 27> value{};
    for (std::size_t a = 0; a < n; ++a)
    {
        double* out = &array.values[a * static_cast<std::size_t>(shown)];
        std::copy(padding.begin(), padding.end(), out);
        field.array->get(a, value.data());
        for (int c = 0; c < native; ++c)
        {
            out[display ? displayIndex<D>(spec.kind(), c) : c] = value[static_cast<std::size_t>(c)];
        }
    }
    if (display && spec.kind() == FieldKind::tensor)
    {
        array.componentNames = {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"};
    }
    if (spec.isSinglePrecision())
    {
        array.singles.assign(array.values.begin(), array.values.end());
        array.values.clear();
    }
    return array;
}

InputError restartError(const std::string& file, const std::string& what)
{
    return InputError("cannot restart from '" + file + "': " + what,
                      {"It was written by an older or different program, or for another case; "
                       "start afresh with startFrom startTime."});
}

} // namespace

template <int D>
void writeState(const ParticleFields<D>& fields, const RunScalars& scalars, double time,
                VtuData& data)
{
    const std::size_t n = fields.size();
    for (const auto& field : fields.all())
    {
        const FieldSpec& spec = field.spec;
        if (spec.isScratch())
        {
            continue;
        }
        if (spec.name() == positionField)
        {
            data.points.assign(3 * n, 0.0);
            std::array<double, 3> x{};
            for (std::size_t a = 0; a < n; ++a)
            {
                field.array->get(a, x.data());
                std::copy(x.begin(), x.begin() + D, &data.points[3 * a]);
            }
            continue;
        }
        data.pointData[spec.fileName()] = arrayOf<D>(field, n);
        if (spec.isActive())
        {
            std::string& active = spec.kind() == FieldKind::vector   ? data.activeVectors
                                  : spec.kind() == FieldKind::tensor ? data.activeTensors
                                                                     : data.activeScalars;
            if (!active.empty())
            {
                throw std::logic_error("two active " + toString(spec.kind()) + " fields: " +
                                       active + " and " + spec.name());
            }
            active = spec.fileName();
        }
    }
    data.fieldData["TimeValue"] = VtuArray{1, {time}, false, {}, {}};
    for (const auto& scalar : scalars.all())
    {
        data.fieldData[restartPrefix + scalar.name] = VtuArray{1, {scalar.get()}, false, {}, {}};
    }
    for (const auto& array : scalars.arrays())
    {
        data.fieldData[restartPrefix + array.name] = VtuArray{1, *array.values, false, {}, {}};
    }
}

template <int D>
void readState(const VtuData& data, ParticleFields<D>& fields, const RunScalars& scalars,
               const std::string& file)
{
    const std::size_t n = fields.size();
    if (data.pointCount() != n)
    {
        throw restartError(file, "it holds " + std::to_string(data.pointCount()) +
                                     " particles, the case " + std::to_string(n));
    }
    for (auto& field : fields.all())
    {
        const FieldSpec& spec = field.spec;
        if (!spec.isRestart())
        {
            continue;
        }
        const int native = field.components();
        field.array->resize(n);
        std::array<double, 27> value{};
        if (spec.name() == positionField)
        {
            for (std::size_t a = 0; a < n; ++a)
            {
                std::copy(&data.points[3 * a], &data.points[3 * a] + D, value.begin());
                field.array->set(a, value.data());
            }
            continue;
        }
        const auto found = data.pointData.find(spec.fileName());
        if (found == data.pointData.end())
        {
            throw restartError(file, "it has no array '" + spec.fileName() + "'");
        }
        const VtuArray& array = found->second;
        const bool display = spec.isDisplay();
        const int stored = display ? displayComponents(spec.kind()) : native;
        if (array.components != stored ||
            array.values.size() != n * static_cast<std::size_t>(stored))
        {
            throw restartError(file, "its array '" + spec.fileName() + "' has " +
                                         std::to_string(array.components) + " components, not " +
                                         std::to_string(stored));
        }
        for (std::size_t a = 0; a < n; ++a)
        {
            const double* in = &array.values[a * static_cast<std::size_t>(stored)];
            for (int c = 0; c < native; ++c)
            {
                value[static_cast<std::size_t>(c)] = in[display ? displayIndex<D>(spec.kind(), c) : c];
            }
            field.array->set(a, value.data());
        }
    }
    for (const auto& scalar : scalars.all())
    {
        const auto found = data.fieldData.find(restartPrefix + scalar.name);
        if (found == data.fieldData.end() || found->second.values.size() != 1)
        {
            throw restartError(file, "it has no number '" + std::string(restartPrefix) + scalar.name + "'");
        }
        scalar.set(found->second.values[0]);
    }
    for (const auto& array : scalars.arrays())
    {
        const auto found = data.fieldData.find(restartPrefix + array.name);
        if (found == data.fieldData.end() || found->second.components != 1)
        {
            throw restartError(file, "it has no array '" + std::string(restartPrefix) + array.name + "'");
        }
        *array.values = found->second.values;
    }
}

template void writeState<1>(const ParticleFields<1>&, const RunScalars&, double, VtuData&);
template void writeState<2>(const ParticleFields<2>&, const RunScalars&, double, VtuData&);
template void writeState<3>(const ParticleFields<3>&, const RunScalars&, double, VtuData&);
template void readState<1>(const VtuData&, ParticleFields<1>&, const RunScalars&, const std::string&);
template void readState<2>(const VtuData&, ParticleFields<2>&, const RunScalars&, const std::string&);
template void readState<3>(const VtuData&, ParticleFields<3>&, const RunScalars&, const std::string&);

} // namespace sph
