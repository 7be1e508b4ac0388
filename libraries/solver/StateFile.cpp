#include "solver/StateFile.hpp"

#include "core/InputError.hpp"
#include "io/VtuChecks.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <memory>
#include <variant>

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

// The written points [begin, end) of `field`: point k is particle k, or (*selection)[k]. A stored
// field of doubles is streamed (the file reads it from the particles as it is written: no copy
// of it); a derived one (which may compute, e.g. a return map) and integer or single-precision
// arrays are copied.
template <int D>
VtuArray arrayOf(const typename ParticleFields<D>::Field& field, const std::vector<std::size_t>* selection,
                 std::size_t begin, std::size_t end)
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
    // Point k's values as written (a display tensor 3×3, a display vector 3, padded).
    const auto copyOut = [array = field.array.get(), selection, native, display, kind = spec.kind(),
                          padding](std::size_t k, double* out) {
        std::copy(padding.begin(), padding.end(), out);
        std::array<double, 27> value{};
        array->get(selection ? (*selection)[k] : k, value.data());
        for (int c = 0; c < native; ++c)
        {
            out[display ? displayIndex<D>(kind, c) : c] = value[static_cast<std::size_t>(c)];
        }
    };
    VtuArray array;
    array.components = shown;
    array.integer = spec.kind() == FieldKind::integer;
    array.single = spec.isSinglePrecision();
    if (display && spec.kind() == FieldKind::tensor)
    {
        array.componentNames = {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"};
    }
    if (field.array->stored() && !array.integer && !array.single)
    {
        auto source = std::make_shared<VtuStreamedValues>();
        source->width = static_cast<std::size_t>(shown);
        source->items = end - begin;
        source->get = [copyOut, begin](std::size_t item, double* out) { copyOut(begin + item, out); };
        array.streamed = std::move(source);
        return array;
    }
    array.values.resize((end - begin) * static_cast<std::size_t>(shown));
    for (std::size_t k = begin; k < end; ++k)
    {
        copyOut(k, &array.values[(k - begin) * static_cast<std::size_t>(shown)]);
    }
    if (array.single)
    {
        array.singles.assign(array.values.begin(), array.values.end());
        array.values = {};
    }
    return array;
}

const char* const restartHint = "It was written by an older or different program, or for another "
                                "case, or damaged; start afresh with startFrom startTime.";

InputError restartError(const std::string& file, const std::string& what)
{
    return InputError("cannot restart from '" + file + "': " + what, {restartHint});
}

// The restart arrays of a run scalar: whole numbers for a counter (a step of 1e300 or NaN does
// not fit a long), any finite number otherwise.
void checkScalar(const VtuChecks& checks, const RunScalars::Scalar& scalar, const VtuArray& array)
{
    if (std::holds_alternative<long*>(scalar.value))
    {
        checks.wholeNumbers(restartPrefix + scalar.name, array, -9.0e18, 9.0e18, "a counter");
    }
}

// The time and every other restart number (time-step state, function-object state) are used
// as they are: one finite value each; a run array, or a ragged particle field's entries, may
// hold any number of finite values.
void checkRestartFieldData(const VtuChecks& checks, const VtuData& data, const RunScalars& scalars,
                           const std::vector<std::string>& raggedNames)
{
    checks.fieldArray("TimeValue", 1);
    for (const auto& [name, array] : data.fieldData)
    {
        if (name.rfind(restartPrefix, 0) != 0)
        {
            continue;
        }
        const bool runArray =
            std::any_of(scalars.arrays().begin(), scalars.arrays().end(),
                        [&](const RunScalars::Array& a) { return restartPrefix + a.name == name; }) ||
            std::find(raggedNames.begin(), raggedNames.end(), name) != raggedNames.end();
        const bool scalar =
            std::any_of(scalars.all().begin(), scalars.all().end(),
                        [&](const RunScalars::Scalar& s) { return restartPrefix + s.name == name; });
        if (!runArray && !scalar && array.values.size() != 1)
        {
            // An array of another setting's model (gradF's per-sample history read by a run
            // without it): say so rather than that it is not one number.
            checks.fail("it holds the restart array '" + name + "' (" +
                        std::to_string(array.values.size()) +
                        " values), which none of this run's models keeps: it was written with "
                        "other settings (scheme, its options, material) than this run's");
        }
        checks.fieldArray(name, runArray ? 0 : 1);
    }
    // The solver's step counter (written with the output) becomes a long.
    const auto step = data.fieldData.find(std::string(restartPrefix) + "step");
    if (step != data.fieldData.end())
    {
        checks.wholeNumbers(step->first, step->second, 0, 9.0e18, "the step count");
    }
}

// A ragged particle field: each particle's entry count (point data), then the entries of all
// of them, one particle after another (field data, one tuple per entry).
void readRagged(const VtuChecks& checks, RaggedArray& ragged, std::size_t n)
{
    const std::string countName = restartPrefix + ragged.name() + raggedCountSuffix;
    const VtuArray& countArray = checks.pointArray(countName, 1);
    checks.wholeNumbers(countName, countArray, 0, 1e9, "a number of entries");
    std::vector<std::size_t> counts(n);
    std::size_t total = 0;
    for (std::size_t a = 0; a < n; ++a)
    {
        counts[a] = static_cast<std::size_t>(countArray.values[a]);
        total += counts[a];
    }
    const std::string name = restartPrefix + ragged.name();
    const VtuArray& entries = checks.fieldArray(name, 0);
    if (entries.values.size() != total * ragged.width() ||
        (total > 0 && entries.components != static_cast<int>(ragged.width())))
    {
        checks.fail("its field data '" + name + "' holds " + std::to_string(entries.values.size()) +
                    " values in tuples of " + std::to_string(entries.components) + ", not " +
                    std::to_string(total) + " entries of " + std::to_string(ragged.width()) +
                    " as its point array '" + countName + "' says");
    }
    ragged.assign(counts, entries.values);
}

} // namespace

template <int D>
void writeStateHeader(const ParticleFields<D>& fields, const RunScalars& scalars, double time,
                      VtuData& header, const std::vector<std::size_t>* selection)
{
    for (const auto& field : fields.all())
    {
        const FieldSpec& spec = field.spec;
        if (spec.isScratch() || spec.name() == positionField || !spec.isActive())
        {
            continue;
        }
        std::string& active = spec.kind() == FieldKind::vector   ? header.activeVectors
                              : spec.kind() == FieldKind::tensor ? header.activeTensors
                                                                 : header.activeScalars;
        if (!active.empty())
        {
            throw std::logic_error("two active " + toString(spec.kind()) + " fields: " + active +
                                   " and " + spec.name());
        }
        active = spec.fileName();
    }
    header.fieldData["TimeValue"] = VtuArray{1, {time}, false, {}, {}};
    for (const auto& scalar : scalars.all())
    {
        header.fieldData[restartPrefix + scalar.name] = VtuArray{1, {scalar.get()}, false, {}, {}};
    }
    for (const auto& array : scalars.arrays())
    {
        header.fieldData[restartPrefix + array.name] = VtuArray{1, *array.values, false, {}, {}};
    }
    // The entries of the written particles, in their order (their counts are point data),
    // streamed to the file as it is written: no copy of them (gradF's samples are the largest
    // data of a plastic run; a copy cost 6.4 kB per particle at each output of the 3D Taylor bar).
    for (const RaggedArray* ragged : fields.ragged())
    {
        const std::size_t n = selection ? selection->size() : fields.size();
        auto source = std::make_shared<VtuStreamedValues>();
        source->offsets.resize(n + 1, 0);
        for (std::size_t k = 0; k < n; ++k)
        {
            source->offsets[k + 1] = source->offsets[k] +
                                     ragged->entries(selection ? (*selection)[k] : k) * ragged->width();
        }
        source->get = [ragged, selection](std::size_t k, double* out) {
            ragged->get(selection ? (*selection)[k] : k, out);
        };
        VtuArray entries{static_cast<int>(ragged->width()), {}, false, {}, {}};
        entries.streamed = std::move(source);
        header.fieldData[restartPrefix + ragged->name()] = std::move(entries);
    }
}

template <int D>
void writeStatePoints(const ParticleFields<D>& fields, const std::vector<std::size_t>* selection,
                      std::size_t begin, std::size_t end, VtuData& piece)
{
    for (const auto& field : fields.all())
    {
        const FieldSpec& spec = field.spec;
        if (spec.isScratch())
        {
            continue;
        }
        if (spec.name() == positionField)
        {
            piece.points.assign(3 * (end - begin), 0.0);
            std::array<double, 3> x{};
            for (std::size_t k = begin; k < end; ++k)
            {
                field.array->get(selection ? (*selection)[k] : k, x.data());
                std::copy(x.begin(), x.begin() + D, &piece.points[3 * (k - begin)]);
            }
            continue;
        }
        piece.pointData[spec.fileName()] = arrayOf<D>(field, selection, begin, end);
    }
    for (const RaggedArray* ragged : fields.ragged())
    {
        VtuArray counts{1, std::vector<double>(end - begin), true, {}, {}};
        for (std::size_t k = begin; k < end; ++k)
        {
            counts.values[k - begin] = static_cast<double>(ragged->entries(selection ? (*selection)[k] : k));
        }
        piece.pointData[restartPrefix + ragged->name() + raggedCountSuffix] = std::move(counts);
    }
}

template <int D>
void writeState(const ParticleFields<D>& fields, const RunScalars& scalars, double time,
                VtuData& data)
{
    writeStateHeader<D>(fields, scalars, time, data);
    writeStatePoints<D>(fields, nullptr, 0, fields.size(), data);
    // The data outlives this call: no reference to the fields.
    for (auto* arrays : {&data.fieldData, &data.pointData})
    {
        for (auto& [name, array] : *arrays)
        {
            materialise(array);
        }
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
    const VtuChecks checks(data, "cannot restart from '" + file + "'", restartHint);
    std::vector<std::string> raggedNames;
    for (const RaggedArray* ragged : fields.ragged())
    {
        raggedNames.push_back(restartPrefix + ragged->name());
    }
    checkRestartFieldData(checks, data, scalars, raggedNames);
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
            checks.finitePoints();
            for (std::size_t a = 0; a < n; ++a)
            {
                std::copy(&data.points[3 * a], &data.points[3 * a] + D, value.begin());
                field.array->set(a, value.data());
            }
            continue;
        }
        const bool display = spec.isDisplay();
        const int stored = display ? displayComponents(spec.kind()) : native;
        // Restart data this run's models declare but the writer's may not have: say what it
        // is, so that a changed setting (a new scheme option, a probe) is recognisable.
        const VtuArray& array = checks.pointArray(
            spec.fileName(), stored,
            "(" + spec.description() + "): the run that wrote it did not use the model that "
            "keeps it; start afresh, or restart with the settings it was written with");
        if (spec.kind() == FieldKind::integer)
        {
            // Integer fields are flags and ids held in an int (or narrower).
            checks.wholeNumbers(spec.fileName(), array, std::numeric_limits<int>::min(),
                                std::numeric_limits<int>::max(), "an integer field");
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
    for (RaggedArray* ragged : fields.ragged())
    {
        readRagged(checks, *ragged, n);
    }
    for (const auto& scalar : scalars.all())
    {
        const VtuArray& array = checks.fieldArray(restartPrefix + scalar.name, 1);
        checkScalar(checks, scalar, array);
        scalar.set(array.values[0]);
    }
    for (const auto& array : scalars.arrays())
    {
        const VtuArray& stored = checks.fieldArray(restartPrefix + array.name, 0);
        if (stored.components != 1)
        {
            checks.fail("its field data '" + std::string(restartPrefix) + array.name + "' has " +
                        std::to_string(stored.components) + " components, not 1");
        }
        *array.values = stored.values;
    }
}

#define SPH_STATE_FILE_WRITERS(D)                                                                  \
    template void writeStateHeader<D>(const ParticleFields<D>&, const RunScalars&, double, VtuData&, \
                                      const std::vector<std::size_t>*);                              \
    template void writeStatePoints<D>(const ParticleFields<D>&, const std::vector<std::size_t>*,     \
                                      std::size_t, std::size_t, VtuData&);
SPH_STATE_FILE_WRITERS(1)
SPH_STATE_FILE_WRITERS(2)
SPH_STATE_FILE_WRITERS(3)
#undef SPH_STATE_FILE_WRITERS
template void writeState<1>(const ParticleFields<1>&, const RunScalars&, double, VtuData&);
template void writeState<2>(const ParticleFields<2>&, const RunScalars&, double, VtuData&);
template void writeState<3>(const ParticleFields<3>&, const RunScalars&, double, VtuData&);
template void readState<1>(const VtuData&, ParticleFields<1>&, const RunScalars&, const std::string&);
template void readState<2>(const VtuData&, ParticleFields<2>&, const RunScalars&, const std::string&);
template void readState<3>(const VtuData&, ParticleFields<3>&, const RunScalars&, const std::string&);

} // namespace sph
