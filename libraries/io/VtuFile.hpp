#pragma once
// Point sets in VTK's XML unstructured-grid format (.vtu), written and read with the VTK
// library: one VTK_VERTEX cell per point so ParaView shows the particles; appended binary data,
// zlib-compressed; points and restart arrays in double precision so a file can restart a run
// exactly, display-only arrays may be single precision. Written atomically (temp + rename);
// VTK reads the arrays in place (no copy), and a run's output is streamed in pieces
// (writeVtuInPieces), so writing costs a few megabytes beyond the data, whatever its size.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace sph
{

// Values that are not held in memory but copied out, item by item, when the writer reaches them:
// get(i, out) copies item i's values to out. Either every item holds `width` values (`items` of
// them: a particle field, an item per particle), or, with width 0, item i holds offsets[i + 1] -
// offsets[i] values (offsets[0] = 0: a ragged particle field, gradF's samples the largest data
// of a plastic run). Written so, a field costs the output no copy of it.
struct VtuStreamedValues
{
    std::size_t width = 0;
    std::size_t items = 0;
    std::vector<std::size_t> offsets;
    std::function<void(std::size_t item, double* out)> get;

    bool fixedWidth() const { return width > 0; }
    std::size_t itemCount() const
    {
        return fixedWidth() ? items : offsets.empty() ? 0 : offsets.size() - 1;
    }
    std::size_t size() const { return first(itemCount()); }
    // The index of item i's first value (first(itemCount()) = size()).
    std::size_t first(std::size_t item) const
    {
        return fixedWidth() ? item * width : offsets.empty() ? 0 : offsets[item];
    }
};

struct VtuArray
{
    int components = 1;
    std::vector<double> values; // components per point (or per tuple), row-major
    bool integer = false;       // stored as Int32 (ids, flags) instead of Float64
    // Names of the components shown by ParaView ("XX", "XY", ...); empty for defaults.
    std::vector<std::string> componentNames;
    std::vector<float> singles; // the values of a `single` array
    bool readFromSingles = false; // (read back) the file stores it as Float32
    bool single = false;          // written as Float32, from `singles`
    // Written from these instead of `values`, which stays empty (not with `integer` or
    // `single`); they read their source when the file is written, so it must not change before.
    std::shared_ptr<const VtuStreamedValues> streamed = nullptr;

    // The number of values it holds, wherever they are.
    std::size_t size() const
    {
        return streamed ? streamed->size() : single ? singles.size() : values.size();
    }
};

// The values of `array` in memory (a streamed array's copied into `values`; others unchanged).
void materialise(VtuArray& array);

// A field-data array X whose tuples belong to the points, a variable number each (a ragged
// particle field, particles/RaggedArray.hpp): the point array X + raggedCountSuffix says how
// many tuples each point has, and the tuples follow the points' order. readPvtu keeps it so
// when it joins pieces.
inline constexpr const char* raggedCountSuffix = "Count";

struct VtuData
{
    std::vector<double> points;                  // 3 per point
    std::map<std::string, VtuArray> pointData;   // per-point arrays, by name
    std::map<std::string, VtuArray> fieldData;   // whole-dataset arrays (TimeValue, ...)
    std::map<std::string, std::vector<std::string>> stringFields; // e.g. body names
    // The point arrays ParaView uses when nothing else is chosen (empty: none).
    std::string activeScalars;
    std::string activeVectors;
    std::string activeTensors;

    std::size_t pointCount() const { return points.size() / 3; }
};

void writeVtu(const std::filesystem::path& file, const VtuData& data);

// Fills `piece` with the points [begin, end) of a dataset: their positions and point arrays
// (the same arrays for every range; field data is not read from it).
using VtuPieceFill = std::function<void(std::size_t begin, std::size_t end, VtuData& piece)>;

// Points per piece of writeVtuInPieces: a few megabytes of arrays at a time.
inline constexpr std::size_t defaultVtuPieceSize = 1u << 13;

// The same file for `points` points made piece by piece: VTK's writer asks `fill` for one range
// of at most `pieceSize` points at a time and streams it into the file, so only one piece's
// arrays exist at any moment (a full copy of every written field costs a run 0.3-0.7 kB per
// particle at each output). `header` gives the field data, string fields and active arrays.
// ParaView and readVtu see one dataset, the pieces joined in order.
void writeVtuInPieces(const std::filesystem::path& file, const VtuData& header, std::size_t points,
                      const VtuPieceFill& fill, std::size_t pieceSize = defaultVtuPieceSize);

// Reads a .vtu (any point arrays; field data of numbers or strings). Errors are InputErrors
// naming the file.
VtuData readVtu(const std::filesystem::path& file);

} // namespace sph
