#include "io/VtuFile.hpp"

#include "core/Format.hpp"
#include "core/InputError.hpp"
#include "core/IoError.hpp"
#include "io/AtomicFile.hpp"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkExecutive.h>
#include <vtkFloatArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace sph
{

namespace
{

// Collects VTK's error messages instead of letting VTK print them.
class ErrorCollector
{
public:
    explicit ErrorCollector(vtkObject* object)
    {
        callback_->SetClientData(this);
        callback_->SetCallback([](vtkObject*, unsigned long, void* self, void* text) {
            auto* collector = static_cast<ErrorCollector*>(self);
            if (text)
            {
                collector->messages_ += static_cast<const char*>(text);
            }
        });
        object->AddObserver(vtkCommand::ErrorEvent, callback_);
        object->AddObserver(vtkCommand::WarningEvent, callback_);
    }
    const std::string& messages() const { return messages_; }

private:
    vtkNew<vtkCallbackCommand> callback_;
    std::string messages_;
};

// Why VTK could not write: the system's reason if there is one, else VTK's own words.
std::string writeFailure(unsigned long vtkError, int systemError, const std::string& messages)
{
    if (systemError != 0)
    {
        return IoError::reasonFor(systemError);
    }
    if (vtkError == vtkErrorCode::OutOfDiskSpaceError)
    {
        return IoError::reasonFor(ENOSPC);
    }
    const char* name = vtkErrorCode::GetStringFromErrorCode(vtkError);
    return "VTK: " + (messages.empty() && name ? std::string(name) : messages);
}

// VTK only reads the arrays while writing: they are wrapped, not copied (save = 1: VTK never
// frees them).
template <class Vtk, class T>
vtkSmartPointer<Vtk> wrap(const std::vector<T>& values, int components)
{
    auto array = vtkSmartPointer<Vtk>::New();
    array->SetNumberOfComponents(components);
    array->SetArray(const_cast<T*>(values.data()), static_cast<vtkIdType>(values.size()), 1);
    return array;
}

vtkSmartPointer<vtkDataArray> makeArray(const std::string& name, const VtuArray& array,
                                        std::size_t tuples)
{
    vtkSmartPointer<vtkDataArray> result;
    if (!array.singles.empty())
    {
        result = wrap<vtkFloatArray>(array.singles, array.components);
    }
    else if (array.integer)
    {
        auto values = vtkSmartPointer<vtkIntArray>::New();
        values->SetNumberOfComponents(array.components);
        values->SetNumberOfTuples(static_cast<vtkIdType>(tuples));
        for (std::size_t i = 0; i < array.values.size(); ++i)
        {
            values->SetValue(static_cast<vtkIdType>(i), static_cast<int>(array.values[i]));
        }
        result = values;
    }
    else
    {
        result = wrap<vtkDoubleArray>(array.values, array.components);
    }
    (void)tuples;
    result->SetName(name.c_str());
    for (std::size_t c = 0; c < array.componentNames.size(); ++c)
    {
        result->SetComponentName(static_cast<vtkIdType>(c), array.componentNames[c].c_str());
    }
    return result;
}

VtuArray readArray(vtkDataArray* source)
{
    VtuArray array;
    array.components = source->GetNumberOfComponents();
    array.integer = source->GetDataType() == VTK_INT || source->GetDataType() == VTK_LONG ||
                    source->GetDataType() == VTK_ID_TYPE || source->GetDataType() == VTK_LONG_LONG;
    array.readFromSingles = source->GetDataType() == VTK_FLOAT;
    const vtkIdType tuples = source->GetNumberOfTuples();
    array.values.resize(static_cast<std::size_t>(tuples * array.components));
    for (vtkIdType t = 0; t < tuples; ++t)
    {
        for (int c = 0; c < array.components; ++c)
        {
            array.values[static_cast<std::size_t>(t * array.components + c)] =
                source->GetComponent(t, c);
        }
    }
    for (int c = 0; c < array.components; ++c)
    {
        if (const char* name = source->GetComponentName(c))
        {
            array.componentNames.emplace_back(name);
        }
    }
    return array;
}

// A value in a message: the shortest form that reads back exactly (0.5, 7, 1e+300, nan), so
// that 7.0000001 is not shown as a whole 7.
std::string exact(double value)
{
    for (int digits = 6; digits < 17; ++digits)
    {
        const std::string text = formatNumber(value, digits);
        if (std::strtod(text.c_str(), nullptr) == value)
        {
            return text;
        }
    }
    return formatNumber(value, 17);
}

} // namespace

void writeVtu(const std::filesystem::path& file, const VtuData& data)
{
    const std::size_t n = data.pointCount();
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetData(wrap<vtkDoubleArray>(data.points, 3));
    grid->SetPoints(points);
    // One vertex cell per point.
    auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
    auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
    offsets->SetNumberOfValues(static_cast<vtkIdType>(n + 1));
    connectivity->SetNumberOfValues(static_cast<vtkIdType>(n));
    for (std::size_t i = 0; i <= n; ++i)
    {
        offsets->SetValue(static_cast<vtkIdType>(i), static_cast<vtkIdType>(i));
        if (i < n)
        {
            connectivity->SetValue(static_cast<vtkIdType>(i), static_cast<vtkIdType>(i));
        }
    }
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    cells->SetData(offsets, connectivity);
    grid->SetCells(VTK_VERTEX, cells);

    for (const auto& [name, array] : data.pointData)
    {
        const std::size_t size = array.singles.empty() ? array.values.size() : array.singles.size();
        if (size != n * static_cast<std::size_t>(array.components))
        {
            throw std::logic_error("point array '" + name + "' has the wrong size");
        }
        grid->GetPointData()->AddArray(makeArray(name, array, n));
    }
    if (!data.activeScalars.empty())
    {
        grid->GetPointData()->SetActiveScalars(data.activeScalars.c_str());
    }
    if (!data.activeVectors.empty())
    {
        grid->GetPointData()->SetActiveVectors(data.activeVectors.c_str());
    }
    if (!data.activeTensors.empty())
    {
        grid->GetPointData()->SetActiveTensors(data.activeTensors.c_str());
    }
    for (const auto& [name, array] : data.fieldData)
    {
        grid->GetFieldData()->AddArray(
            makeArray(name, array, array.values.size() / static_cast<std::size_t>(array.components)));
    }
    for (const auto& [name, strings] : data.stringFields)
    {
        auto array = vtkSmartPointer<vtkStringArray>::New();
        array->SetName(name.c_str());
        for (const auto& s : strings)
        {
            array->InsertNextValue(s);
        }
        grid->GetFieldData()->AddArray(array);
    }

    writeAtomically(file, [&](const std::filesystem::path& temporary) {
        auto writer = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
        ErrorCollector errors(writer);
        // A failed write is also reported by the pipeline's executive, printed unless caught.
        ErrorCollector pipelineErrors(writer->GetExecutive());
        writer->SetFileName(temporary.c_str());
        writer->SetInputData(grid);
        writer->SetDataModeToAppended();
        writer->EncodeAppendedDataOff();
        writer->SetCompressorTypeToZLib();
        // VTK reports a failed write by its result and error code (a full disk stops its
        // stream); the reason is the system's, from errno, when the stream left one.
        errno = 0;
        const int written = writer->Write();
        const int error = errno;
        if (written != 1 || writer->GetErrorCode() != vtkErrorCode::NoError ||
            !errors.messages().empty())
        {
            throw IoError(file, writeFailure(writer->GetErrorCode(), error, errors.messages()));
        }
    });
}

VtuData readVtu(const std::filesystem::path& file)
{
    if (!std::filesystem::is_regular_file(file))
    {
        throw InputError("cannot find the VTK file '" + file.string() + "'");
    }
    auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    ErrorCollector errors(reader);
    if (!reader->CanReadFile(file.c_str()))
    {
        throw InputError("'" + file.string() + "' is not a readable VTK unstructured grid (.vtu)",
                         {"It may be damaged, or written by another program in another format."});
    }
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    if (!errors.messages().empty() || !grid || !grid->GetPoints())
    {
        throw InputError("cannot read '" + file.string() + "'",
                         {"VTK: " + errors.messages()});
    }
    VtuData data;
    const vtkIdType n = grid->GetNumberOfPoints();
    data.points.resize(static_cast<std::size_t>(3 * n));
    for (vtkIdType i = 0; i < n; ++i)
    {
        grid->GetPoint(i, &data.points[static_cast<std::size_t>(3 * i)]);
    }
    vtkPointData* pointData = grid->GetPointData();
    const auto activeName = [](vtkDataArray* array) {
        return array && array->GetName() ? std::string(array->GetName()) : std::string();
    };
    data.activeScalars = activeName(pointData->GetScalars());
    data.activeVectors = activeName(pointData->GetVectors());
    data.activeTensors = activeName(pointData->GetTensors());
    for (int i = 0; i < pointData->GetNumberOfArrays(); ++i)
    {
        if (vtkDataArray* array = pointData->GetArray(i))
        {
            data.pointData[array->GetName() ? array->GetName() : ""] = readArray(array);
        }
    }
    vtkFieldData* fieldData = grid->GetFieldData();
    for (int i = 0; i < fieldData->GetNumberOfArrays(); ++i)
    {
        vtkAbstractArray* array = fieldData->GetAbstractArray(i);
        const std::string name = array && array->GetName() ? array->GetName() : "";
        if (auto* numbers = vtkDataArray::SafeDownCast(array))
        {
            data.fieldData[name] = readArray(numbers);
        }
        else if (auto* strings = vtkStringArray::SafeDownCast(array))
        {
            std::vector<std::string>& values = data.stringFields[name];
            for (vtkIdType k = 0; k < strings->GetNumberOfValues(); ++k)
            {
                values.push_back(strings->GetValue(k));
            }
        }
    }
    return data;
}

VtuChecks::VtuChecks(const VtuData& data, std::string subject, std::string hint)
    : data_(data), subject_(std::move(subject)), hint_(std::move(hint))
{
}

void VtuChecks::fail(const std::string& problem) const
{
    throw InputError(subject_ + ": " + problem, {hint_});
}

void VtuChecks::failAt(const std::string& name, const VtuArray& array, std::size_t index,
                       const std::string& problem) const
{
    const auto components = static_cast<std::size_t>(std::max(1, array.components));
    if (perPoint(array))
    {
        fail(particle(index / components) + ": its array '" + name + "' " + problem);
    }
    fail("its field data '" + name + "'" +
         (array.values.size() > 1 ? " (value " + std::to_string(index) + ")" : "") + " " + problem);
}

// A particle by index, with its position when the position itself is sound.
std::string VtuChecks::particle(std::size_t index) const
{
    std::string text = "particle " + std::to_string(index);
    if (3 * index + 2 < data_.points.size())
    {
        const double* x = &data_.points[3 * index];
        if (std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]))
        {
            text += " (at " + formatNumber(x[0]) + " " + formatNumber(x[1]) + " " +
                    formatNumber(x[2]) + ")";
        }
    }
    return text;
}

// Arrays taken from the point data are per point; the others are field data.
bool VtuChecks::perPoint(const VtuArray& array) const
{
    for (const auto& [name, candidate] : data_.pointData)
    {
        if (&candidate == &array)
        {
            return true;
        }
    }
    return false;
}

void VtuChecks::finitePoints() const
{
    for (std::size_t i = 0; i < data_.points.size(); ++i)
    {
        if (!std::isfinite(data_.points[i]))
        {
            const double* x = &data_.points[i - i % 3];
            fail(particle(i / 3) + " has the position (" + formatNumber(x[0]) + " " +
                 formatNumber(x[1]) + " " + formatNumber(x[2]) +
                 "); every coordinate must be finite");
        }
    }
}

const VtuArray& VtuChecks::pointArray(const std::string& name, int components) const
{
    const auto found = data_.pointData.find(name);
    if (found == data_.pointData.end())
    {
        fail("it has no array '" + name + "'");
    }
    const VtuArray& array = found->second;
    if (array.components != components)
    {
        fail("its array '" + name + "' has " + std::to_string(array.components) +
             " components, not " + std::to_string(components));
    }
    const std::size_t expected = data_.pointCount() * static_cast<std::size_t>(components);
    if (array.values.size() != expected)
    {
        fail("its array '" + name + "' holds " + std::to_string(array.values.size()) +
             " values for " + std::to_string(data_.pointCount()) + " particles (" +
             std::to_string(expected) + " expected)");
    }
    finite(name, array);
    return array;
}

const VtuArray& VtuChecks::fieldArray(const std::string& name, std::size_t size) const
{
    const auto found = data_.fieldData.find(name);
    if (found == data_.fieldData.end())
    {
        fail("it has no field data '" + name + "'");
    }
    const VtuArray& array = found->second;
    if (size > 0 && array.values.size() != size)
    {
        fail("its field data '" + name + "' holds " + std::to_string(array.values.size()) +
             " values, not " + std::to_string(size));
    }
    finite(name, array);
    return array;
}

void VtuChecks::finite(const std::string& name, const VtuArray& array) const
{
    for (std::size_t i = 0; i < array.values.size(); ++i)
    {
        if (!std::isfinite(array.values[i]))
        {
            failAt(name, array, i, "is " + exact(array.values[i]) + "; it must be finite");
        }
    }
}

void VtuChecks::positive(const std::string& name, const VtuArray& array) const
{
    for (std::size_t i = 0; i < array.values.size(); ++i)
    {
        if (!(array.values[i] > 0.0))
        {
            failAt(name, array, i, "is " + exact(array.values[i]) + "; it must be > 0");
        }
    }
}

void VtuChecks::wholeNumbers(const std::string& name, const VtuArray& array, double lowest,
                             double highest, const std::string& meaning) const
{
    for (std::size_t i = 0; i < array.values.size(); ++i)
    {
        const double value = array.values[i];
        if (!(value >= lowest && value <= highest) || value != std::floor(value))
        {
            failAt(name, array, i,
                   "is " + exact(value) + "; it must be a whole number from " + exact(lowest) +
                       " to " + exact(highest) + " (" + meaning + ")");
        }
    }
}

} // namespace sph
