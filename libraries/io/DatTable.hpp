#pragma once
// Reads the tables the function objects write (functionObjects/DatFile): one '#' header line
// of column names (`# time col1 col2 ...`), then rows of whitespace-separated numbers. Later
// '#' lines and blank lines are skipped. Every reader of these tables (sphStudy, the tests)
// goes through here, so a malformed file is always reported the same way: `file:line:col`.

#include <filesystem>
#include <string>
#include <vector>

namespace sph
{

struct DatTable
{
    std::filesystem::path file;
    std::vector<std::string> columns;      // every column, as in the header (first: time)
    std::vector<std::vector<double>> rows; // each as many values as there are columns

    // The index of column `name`, or of its 1-based number when no column has that name
    // (referenceColumn "2"). InputError naming the file, the valid columns and the closest.
    std::size_t columnIndex(const std::string& name) const;
    // The values of column `name` (see columnIndex), one per row.
    std::vector<double> column(const std::string& name) const;
    // The values of column `index` (0: time); std::out_of_range past the last column.
    std::vector<double> columnAt(std::size_t index) const;
    bool hasColumn(const std::string& name) const;
};

enum class DatHeader
{
    required, // a table written by a function object
    optional  // a reference table written by hand: without a header its columns are "1", "2", ...
};

// Reads `file`. InputError (with file:line:col and the line) for a file that cannot be read, a
// missing header, a value that is not a number or a row with the wrong number of values.
DatTable readDatTable(const std::filesystem::path& file, DatHeader header = DatHeader::required);

} // namespace sph
