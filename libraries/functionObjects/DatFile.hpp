#pragma once
// A gnuplot-ready table: one '#' header line of column names, then rows of numbers, first
// column `time`. Every row is handed to the system as it is written, so a killed run keeps what
// it wrote; a row that cannot be written (disk full) is cut off whole and stops the run with an
// IoError (io/CheckedFile). A restart keeps the rows before its start time and appends.

#include "io/CheckedFile.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sph
{

class DatFile
{
public:
    DatFile(std::filesystem::path file, std::vector<std::string> columns);

    void open(double startTime, bool restarted);
    void write(double time, const std::vector<double>& values);
    const std::filesystem::path& path() const { return file_; }
    const std::vector<std::string>& columns() const { return columns_; }

private:
    std::filesystem::path file_;
    std::vector<std::string> columns_;
    std::optional<CheckedFile> out_; // open from open() on
};

} // namespace sph
