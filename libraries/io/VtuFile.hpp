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

// What a reader takes from a .vtu it read, checked where it is taken: the file may be damaged
// or written by another program, and a wrong size, an id out of range or a NaN must be an input
// error naming the file, the array and the particle, not a crash deep in the solver (issue 12
// item 3). Every message starts with `subject` (the file: "constant/particles.vtu", "cannot
// restart from 'VTK/bar_3.vtu'") and ends with `hint`, what to do about the file.
class VtuChecks
{
public:
    VtuChecks(const VtuData& data, std::string subject, std::string hint);

    // Every coordinate of every point is finite.
    void finitePoints() const;
    // Point array `name`: present, `components` per point, every value finite.
    const VtuArray& pointArray(const std::string& name, int components) const;
    // Field-data array `name`: present, `size` values (0: any number, none too), all finite.
    const VtuArray& fieldArray(const std::string& name, std::size_t size) const;
    // Every value of `array` (the point array or field data `name`) is > 0.
    void positive(const std::string& name, const VtuArray& array) const;
    // Whole numbers from `lowest` to `highest`; `meaning` says what the range is.
    void wholeNumbers(const std::string& name, const VtuArray& array, double lowest, double highest,
                      const std::string& meaning) const;

    // Fails about value `index` of `array` (named `name`): particle and position when per point.
    [[noreturn]] void failAt(const std::string& name, const VtuArray& array, std::size_t index,
                             const std::string& problem) const;
    [[noreturn]] void fail(const std::string& problem) const;

    // "particle 3 (at 0.035 0 0)": the position when it is finite.
    std::string particle(std::size_t index) const;

private:
    bool perPoint(const VtuArray& array) const;
    void finite(const std::string& name, const VtuArray& array) const;

    const VtuData& data_;
    std::string subject_;
    std::string hint_;
};

} // namespace sph
