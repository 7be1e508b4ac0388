#pragma once
// The length of each point array of a .vtu as the file stores it, against its piece's
// NumberOfPoints: VTK's reader takes the first NumberOfPoints values and drops the rest
// without a word (a `volume` array of 80 values for 40 points was read as 40; issue 31). Read
// from the XML before VTK reads the file: the values of an ascii array, the byte count in the
// block header of an appended (raw) or inline binary one.

#include <filesystem>

namespace sph
{

// InputError naming the file, the array and both lengths when a point array (or the points)
// holds more or fewer values than NumberOfPoints x NumberOfComponents.
void checkVtuArrayLengths(const std::filesystem::path& file);

} // namespace sph
