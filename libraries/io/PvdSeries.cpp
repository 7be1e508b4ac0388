#include "io/PvdSeries.hpp"

#include "core/Format.hpp"
#include "core/InputError.hpp"
#include "core/TextFile.hpp"
#include "io/AtomicFile.hpp"

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace pt = boost::property_tree;

namespace sph
{

std::string formatSeriesTime(double time)
{
    if (!std::isfinite(time) || time == 0.0)
    {
        return formatShortest(time);
    }
    for (int digits = 1; digits < 17; ++digits)
    {
        const std::string text = formatNumber(time, digits);
        if (std::abs(std::strtod(text.c_str(), nullptr) - time) <=
            seriesTimeTolerance * std::abs(time))
        {
            return text;
        }
    }
    return formatShortest(time); // exact (17 digits at most)
}

PvdSeries::PvdSeries(std::filesystem::path file) : file_(std::move(file)) {}

void PvdSeries::load()
{
    entries_.clear();
    std::error_code ec; // (the throwing overloads report a link loop as an internal error)
    if (std::filesystem::status(file_, ec).type() == std::filesystem::file_type::not_found)
    {
        return;
    }
    const std::string reason = unreadableReason(file_);
    if (!reason.empty())
    {
        throw InputError("cannot read the time series '" + file_.string() + "': " + reason,
                         {"Delete it (and the VTK folder) to start the run afresh."});
    }
    pt::ptree tree;
    try
    {
        pt::read_xml(file_.string(), tree);
        for (const auto& [tag, node] : tree.get_child("VTKFile.Collection"))
        {
            if (tag == "DataSet")
            {
                entries_.push_back({node.get<double>("<xmlattr>.timestep"),
                                    node.get<std::string>("<xmlattr>.file")});
            }
        }
    }
    catch (const pt::ptree_error& error)
    {
        throw InputError("cannot read the time series '" + file_.string() + "': " + error.what(),
                         {"Delete it (and the VTK folder) to start the run afresh."});
    }
}

void PvdSeries::keepThrough(double time)
{
    // A loaded entry holds its time as written, within seriesTimeTolerance of the exact one:
    // the entry of the level at `time` itself may read as a little more.
    const double through = time + 2.0 * seriesTimeTolerance * std::abs(time);
    std::vector<Entry> kept;
    for (const Entry& entry : entries_)
    {
        if (entry.time <= through)
        {
            kept.push_back(entry);
        }
    }
    entries_ = kept;
}

std::vector<std::string> PvdSeries::keepLast(std::size_t count)
{
    std::vector<std::string> dropped;
    while (entries_.size() > count)
    {
        dropped.push_back(entries_.front().file);
        entries_.erase(entries_.begin());
    }
    return dropped;
}

void PvdSeries::add(double time, const std::string& file)
{
    if (!entries_.empty() && entries_.back().file == file)
    {
        entries_.back().time = time;
    }
    else
    {
        entries_.push_back({time, file});
    }
    write();
}

void PvdSeries::write() const
{
    pt::ptree root;
    pt::ptree& vtkFile = root.add("VTKFile", "");
    vtkFile.put("<xmlattr>.type", "Collection");
    vtkFile.put("<xmlattr>.version", "0.1");
    vtkFile.put("<xmlattr>.byte_order", "LittleEndian");
    pt::ptree& collection = vtkFile.add("Collection", "");
    for (const Entry& entry : entries_)
    {
        pt::ptree& dataSet = collection.add("DataSet", "");
        dataSet.put("<xmlattr>.timestep", formatSeriesTime(entry.time));
        dataSet.put("<xmlattr>.group", "");
        dataSet.put("<xmlattr>.part", "0");
        dataSet.put("<xmlattr>.file", entry.file);
    }
    std::ostringstream text;
    pt::write_xml(text, root, pt::xml_writer_make_settings<std::string>(' ', 2));
    writeTextAtomically(file_, text.str());
}

// The output index of `fileName` if it is one of this case's outputs, else -1: "<case>_<n>.vtu"
// (serial), "<case>_<n>.pvtu" and the folder "<case>_<n>" of its pieces (distributed).
long outputIndexOf(const std::string& fileName, const std::string& caseName)
{
    const std::string prefix = caseName + "_";
    std::string suffix;
    for (const char* candidate : {".vtu", ".pvtu"})
    {
        const std::string ending = candidate;
        if (fileName.size() > ending.size() &&
            fileName.compare(fileName.size() - ending.size(), ending.size(), ending) == 0)
        {
            suffix = ending;
        }
    }
    if (fileName.size() <= prefix.size() + suffix.size() || fileName.rfind(prefix, 0) != 0)
    {
        return -1;
    }
    const std::string digits =
        fileName.substr(prefix.size(), fileName.size() - prefix.size() - suffix.size());
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos)
    {
        return -1;
    }
    return std::stol(digits);
}

} // namespace sph
