#pragma once
// Point sets in VTK's XML unstructured-grid format (.vtu), written and read with the VTK
// library: one VTK_VERTEX cell per point so ParaView shows the particles; appended binary data,
// zlib-compressed; points and restart arrays in double precision so a file can restart a run
// exactly, display-only arrays may be single precision. Written atomically (temp + rename);
// VTK reads the arrays in place (no copy), so writing costs little memory beyond the data.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace sph
{

struct VtuArray
{
    int components = 1;
    std::vector<double> values; // components per point (or per tuple), row-major
    bool integer = false;       // stored as Int32 (ids, flags) instead of Float64
    // Names of the components shown by ParaView ("XX", "XY", ...); empty for defaults.
    std::vector<std::string> componentNames;
    std::vector<float> singles; // written as Float32 instead of `values` when not empty
    bool readFromSingles = false; // (read back) the file stores it as Float32
};

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

// Reads a .vtu (any point arrays; field data of numbers or strings). Errors are InputErrors
// naming the file.
VtuData readVtu(const std::filesystem::path& file);

} // namespace sph
