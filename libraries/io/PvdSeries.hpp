#pragma once
// The ParaView time-series file VTK/<case>.pvd (a "Collection" of .vtu files with their
// times). Rewritten atomically after every output, so it is valid at every moment, even if
// the run is killed. Written and read with Boost.PropertyTree's XML support.

#include <filesystem>
#include <string>
#include <vector>

namespace sph
{

class PvdSeries
{
public:
    struct Entry
    {
        double time;
        std::string file; // relative to the .pvd's folder
    };

    explicit PvdSeries(std::filesystem::path file);

    // Reads an existing series (missing file: empty series).
    void load();
    // Keeps only the entries up to `time`, the level a restart starts from (an entry within the
    // series' rounding of `time` is that level's and stays: its file is intact until the
    // restart has written it again, which may fail, e.g. on a full disk; issue 31 item 6).
    void keepThrough(double time);
    // Keeps only the last `count` entries; returns the files of those dropped (the caller
    // rewrites the series first, then deletes them: the series never names a missing file).
    std::vector<std::string> keepLast(std::size_t count);
    // Appends an entry, or replaces the last one when it names the same file (a restart's
    // level written again), and rewrites the file.
    void add(double time, const std::string& file);
    void write() const;

    const std::vector<Entry>& entries() const { return entries_; }
    const std::filesystem::path& file() const { return file_; }

private:
    std::filesystem::path file_;
    std::vector<Entry> entries_;
};

// How far a time in the series may be from the output's exact time, relative: the times are
// for display (ParaView's time slider), and the exact time of a level is its own TimeValue,
// which a restart reads. 1e-12 of the time is what the write schedules count as round-off
// (core/WriteSchedule.hpp); it is above the drift of the output times, sums of intervals
// (0.5 reached as 0.49999999999999994, 8e-5 as 7.9999999999999871e-05), and far below the
// gap between two outputs, a step at least (so two outputs do not show the same time).
inline constexpr double seriesTimeTolerance = 1e-12;

// A time as the series writes it: the fewest significant digits within seriesTimeTolerance
// of it, 0.02 rather than 0.019999999999999997; 17 digits (exact) when none is.
std::string formatSeriesTime(double time);

// The output index of `fileName` if it is one of this case's outputs, else -1: "<case>_<n>.vtu"
// (serial), "<case>_<n>.pvtu" and the folder "<case>_<n>" of its pieces (distributed).
long outputIndexOf(const std::string& fileName, const std::string& caseName);

} // namespace sph
