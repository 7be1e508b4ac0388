#pragma once
// Checks of the arrays a reader takes from a .vtu (io/VtuFile.hpp), each failing with an
// InputError that names the file, the array and the particle.

#include "io/VtuFile.hpp"

#include <filesystem>
#include <string>

namespace sph
{

// What a reader takes from a .vtu it read, checked where it is taken: the file may be damaged
// or written by another program, and a wrong size, an id out of range or a NaN must be an input
// error naming the file, the array and the particle, not a crash deep in the solver (issue 12
// item 3). Every message starts with `subject` (the file: "constant/particles.vtu", "cannot
// restart from 'VTK/bar_3.vtu'") and ends with `hint`, what to do about the file.
// Before VTK reads `file`: its pieces' NumberOfPoints and NumberOfCells (in the XML header, before
// any appended data) are whole numbers >= 0 (VTK takes them unchecked: a negative one crashed
// it); an InputError naming the file otherwise.
void checkVtuPieceSizes(const std::filesystem::path& file);

class VtuChecks
{
public:
    VtuChecks(const VtuData& data, std::string subject, std::string hint);

    // Every coordinate of every point is finite.
    void finitePoints() const;
    // Point array `name`: present, `components` per point, every value finite.
    // `whenMissing`: what the array is and why it may be missing, appended to the message.
    const VtuArray& pointArray(const std::string& name, int components,
                               const std::string& whenMissing = "") const;
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
