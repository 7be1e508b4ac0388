#pragma once
// The summary file of a distributed run's output (.pvtu): it names the pieces every rank wrote
// (.vtu files, io/VtuFile.hpp) and declares their point arrays, so ParaView (or VTK's
// vtkXMLPUnstructuredGridReader) opens them as one dataset. Written atomically with
// Boost.PropertyTree's XML support, like the .pvd series.
//
// VTK's own vtkXMLPUnstructuredGridWriter is not used: it writes the pieces itself, without the
// checked, atomic writes of io/VtuFile (a full disk must never leave a damaged file in place).

#include "io/VtuFile.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sph
{

// `layout` is one piece's data (every piece has the same arrays); `pieces` are the piece files
// relative to the .pvtu's folder, in rank order.
void writePvtu(const std::filesystem::path& file, const VtuData& layout,
               const std::vector<std::string>& pieces);

// A .pvtu's pieces read and joined into one data set, the points in increasing `orderBy` (an
// integer point array every piece holds, numbering the points 0 .. n-1 once each), with the
// field data of the first piece, but for the arrays whose tuples belong to the points
// (raggedCountSuffix): those are joined too, in the points' new order. Errors are InputErrors
// naming the file.
VtuData readPvtu(const std::filesystem::path& file, const std::string& orderBy);

} // namespace sph
