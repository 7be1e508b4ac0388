#include "io/VtuFile.hpp"

#include "core/Format.hpp"
#include "core/InputError.hpp"
#include "core/IoError.hpp"
#include "io/AtomicFile.hpp"
#include "io/VtuArrayLengths.hpp"
#include "io/VtuChecks.hpp"
#include "io/VtuStreamedArray.hpp"

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
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridAlgorithm.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
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
    if (array.streamed)
    {
        auto streamed = vtkSmartPointer<VtuStreamedArray>::New();
        streamed->setSource(array.streamed, array.components);
        result = streamed;
    }
    else if (array.single)
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

} // namespace

namespace
{

// The grid of one piece: its points (one vertex cell each) and point arrays, wrapped, not
// copied (`piece` must outlive the write); the field data and active arrays of `header`.
vtkSmartPointer<vtkUnstructuredGrid> makeGrid(const VtuData& piece, const VtuData& header)
{
    const std::size_t n = piece.pointCount();
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetData(wrap<vtkDoubleArray>(piece.points, 3));
    grid->SetPoints(points);
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

    for (const auto& [name, array] : piece.pointData)
    {
        if (array.size() != n * static_cast<std::size_t>(array.components))
        {
            throw std::logic_error("point array '" + name + "' has the wrong size");
        }
        grid->GetPointData()->AddArray(makeArray(name, array, n));
    }
    if (!header.activeScalars.empty())
    {
        grid->GetPointData()->SetActiveScalars(header.activeScalars.c_str());
    }
    if (!header.activeVectors.empty())
    {
        grid->GetPointData()->SetActiveVectors(header.activeVectors.c_str());
    }
    if (!header.activeTensors.empty())
    {
        grid->GetPointData()->SetActiveTensors(header.activeTensors.c_str());
    }
    for (const auto& [name, array] : header.fieldData)
    {
        grid->GetFieldData()->AddArray(
            makeArray(name, array, array.size() / static_cast<std::size_t>(array.components)));
    }
    for (const auto& [name, strings] : header.stringFields)
    {
        auto array = vtkSmartPointer<vtkStringArray>::New();
        array->SetName(name.c_str());
        for (const auto& s : strings)
        {
            array->InsertNextValue(s);
        }
        grid->GetFieldData()->AddArray(array);
    }
    return grid;
}

// A pipeline source that makes the piece VTK's writer asks for, when it asks: the writer
// streams the pieces of one file through it (vtkXMLUnstructuredDataWriter::SetNumberOfPieces).
class PieceSource : public vtkUnstructuredGridAlgorithm
{
public:
    static PieceSource* New();
    vtkTypeMacro(PieceSource, vtkUnstructuredGridAlgorithm);

    void setUp(const VtuData* header, std::size_t points, std::size_t pieceSize,
               const VtuPieceFill* fill)
    {
        header_ = header;
        points_ = points;
        pieceSize_ = pieceSize;
        fill_ = fill;
    }
    int pieceCount() const
    {
        return static_cast<int>(std::max<std::size_t>(1, (points_ + pieceSize_ - 1) / pieceSize_));
    }

protected:
    PieceSource() { SetNumberOfInputPorts(0); }

    int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
    {
        out->GetInformationObject(0)->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
        return 1;
    }

    int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
    {
        vtkInformation* info = out->GetInformationObject(0);
        const auto piece = static_cast<std::size_t>(
            info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()));
        const auto pieces = static_cast<std::size_t>(
            info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
        if (pieces != static_cast<std::size_t>(pieceCount()))
        {
            vtkErrorMacro("asked for piece " << piece << " of " << pieces << ", made as "
                                             << pieceCount());
            return 0;
        }
        const std::size_t begin = std::min(points_, piece * pieceSize_);
        const std::size_t end = std::min(points_, begin + pieceSize_);
        current_ = VtuData(); // the last piece's arrays go before this one's are made
        (*fill_)(begin, end, current_);
        vtkUnstructuredGrid::GetData(info)->ShallowCopy(makeGrid(current_, *header_));
        return 1;
    }

private:
    const VtuData* header_ = nullptr;
    std::size_t points_ = 0;
    std::size_t pieceSize_ = 1;
    const VtuPieceFill* fill_ = nullptr;
    VtuData current_; // the piece being written (its arrays are wrapped, not copied)
};

vtkStandardNewMacro(PieceSource);

// Writes the grid `connect` gives (its input data or pipeline connection) atomically.
void writeGrid(const std::filesystem::path& file,
               const std::function<void(vtkXMLUnstructuredGridWriter&)>& connect)
{
    writeAtomically(file, [&](const std::filesystem::path& temporary) {
        auto writer = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
        ErrorCollector errors(writer);
        // A failed write is also reported by the pipeline's executive, printed unless caught.
        ErrorCollector pipelineErrors(writer->GetExecutive());
        writer->SetFileName(temporary.c_str());
        connect(*writer);
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
            const std::string messages = errors.messages() + pipelineErrors.messages();
            throw IoError(file, writeFailure(writer->GetErrorCode(), error, messages));
        }
    });
}

} // namespace

void writeVtu(const std::filesystem::path& file, const VtuData& data)
{
    const vtkSmartPointer<vtkUnstructuredGrid> grid = makeGrid(data, data);
    writeGrid(file, [&](vtkXMLUnstructuredGridWriter& writer) { writer.SetInputData(grid); });
}

void writeVtuInPieces(const std::filesystem::path& file, const VtuData& header, std::size_t points,
                      const VtuPieceFill& fill, std::size_t pieceSize)
{
    if (pieceSize == 0)
    {
        throw std::logic_error("writeVtuInPieces: pieces of no points");
    }
    auto source = vtkSmartPointer<PieceSource>::New();
    source->setUp(&header, points, pieceSize, &fill);
    writeGrid(file, [&](vtkXMLUnstructuredGridWriter& writer) {
        writer.SetInputConnection(source->GetOutputPort());
        writer.SetNumberOfPieces(source->pieceCount());
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
    checkVtuPieceSizes(file);
    checkVtuArrayLengths(file);
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

} // namespace sph
