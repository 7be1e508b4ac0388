#pragma once
// A gnuplot-ready table: one '#' header line of column names, then rows of numbers, first
// column `time`. Every row is flushed as it is written, so a killed run keeps what it wrote.
// A restart keeps the rows before its start time and appends.

#include <filesystem>
#include <fstream>
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
    std::ofstream out_;
};

} // namespace sph
