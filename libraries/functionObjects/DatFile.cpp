#include "functionObjects/DatFile.hpp"

#include "io/AtomicFile.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace sph
{

DatFile::DatFile(std::filesystem::path file, std::vector<std::string> columns)
    : file_(std::move(file)), columns_(std::move(columns))
{
}

void DatFile::open(double startTime, bool restarted)
{
    std::string header = "# time";
    for (const auto& column : columns_)
    {
        header += " " + column;
    }
    header += "\n";
    std::string kept = header;
    if (restarted && std::filesystem::exists(file_))
    {
        // Keep the rows written before the restart time; the run writes the rest again.
        std::ifstream in(file_);
        std::string line;
        while (std::getline(in, line))
        {
            if (line.empty() || line[0] == '#')
            {
                continue;
            }
            std::istringstream row(line);
            double time;
            // The table holds 12 digits: compare with a tolerance far below one time step.
            if (row >> time && time < startTime - 1e-9 * std::abs(startTime))
            {
                kept += line + "\n";
            }
        }
    }
    writeTextAtomically(file_, kept);
    out_.emplace(file_, file_, CheckedFile::Mode::append);
}

void DatFile::write(double time, const std::vector<double>& values)
{
    char buffer[32];
    std::string line;
    std::snprintf(buffer, sizeof buffer, "%.12g", time);
    line += buffer;
    for (double value : values)
    {
        std::snprintf(buffer, sizeof buffer, " %.12g", value);
        line += buffer;
    }
    line += '\n';
    out_->write(line);
}

} // namespace sph
