#include "io/PvtuFile.hpp"

#include "core/Format.hpp"
#include "core/InputError.hpp"
#include "io/AtomicFile.hpp"

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <algorithm>
#include <numeric>
#include <sstream>

namespace sph
{

namespace pt = boost::property_tree;

namespace
{

// The type name VTK writes for an array (io/VtuFile.cpp: Int32, Float32 or Float64).
std::string typeOf(const VtuArray& array)
{
    if (array.integer)
    {
        return "Int32";
    }
    return array.single ? "Float32" : "Float64";
}

void declare(pt::ptree& parent, const std::string& name, const std::string& type, int components)
{
    pt::ptree& array = parent.add("PDataArray", "");
    array.put("<xmlattr>.type", type);
    if (!name.empty())
    {
        array.put("<xmlattr>.Name", name);
    }
    array.put("<xmlattr>.NumberOfComponents", components);
}

} // namespace

void writePvtu(const std::filesystem::path& file, const VtuData& layout,
               const std::vector<std::string>& pieces)
{
    pt::ptree root;
    pt::ptree& vtkFile = root.add("VTKFile", "");
    vtkFile.put("<xmlattr>.type", "PUnstructuredGrid");
    vtkFile.put("<xmlattr>.version", "1.0");
    vtkFile.put("<xmlattr>.byte_order", "LittleEndian");
    vtkFile.put("<xmlattr>.header_type", "UInt64");
    pt::ptree& grid = vtkFile.add("PUnstructuredGrid", "");
    grid.put("<xmlattr>.GhostLevel", "0");
    pt::ptree& pointData = grid.add("PPointData", "");
    if (!layout.activeScalars.empty())
    {
        pointData.put("<xmlattr>.Scalars", layout.activeScalars);
    }
    if (!layout.activeVectors.empty())
    {
        pointData.put("<xmlattr>.Vectors", layout.activeVectors);
    }
    if (!layout.activeTensors.empty())
    {
        pointData.put("<xmlattr>.Tensors", layout.activeTensors);
    }
    for (const auto& [name, array] : layout.pointData)
    {
        declare(pointData, name, typeOf(array), array.components);
    }
    declare(grid.add("PPoints", ""), "Points", "Float64", 3);
    pt::ptree& cells = grid.add("PCells", "");
    declare(cells, "connectivity", "Int64", 1);
    declare(cells, "offsets", "Int64", 1);
    declare(cells, "types", "UInt8", 1);
    for (const std::string& piece : pieces)
    {
        grid.add("Piece", "").put("<xmlattr>.Source", piece);
    }
    std::ostringstream text;
    pt::write_xml(text, root, pt::xml_writer_make_settings<std::string>(' ', 2));
    writeTextAtomically(file, text.str());
}

VtuData readPvtu(const std::filesystem::path& file, const std::string& orderBy)
{
    const std::string name = file.string();
    const auto refuse = [&](const std::string& why) {
        throw InputError("cannot read '" + name + "': " + why,
                         {"A distributed run's output is the .pvtu and its pieces in the folder of "
                          "the same name; both are needed."});
    };
    pt::ptree root;
    try
    {
        pt::read_xml(name, root);
    }
    catch (const pt::xml_parser_error& error)
    {
        refuse(error.message());
    }
    // (A child looked up with a default would be a reference to that temporary default.)
    const auto grid = root.get_child_optional("VTKFile.PUnstructuredGrid");
    if (!grid)
    {
        refuse("it holds no <VTKFile><PUnstructuredGrid> (an empty or damaged file)");
    }
    std::vector<std::filesystem::path> pieces;
    for (const auto& [tag, piece] : *grid)
    {
        if (tag == "Piece")
        {
            const std::string source = piece.get<std::string>("<xmlattr>.Source", "");
            if (source.empty())
            {
                refuse("a <Piece> names no Source file");
            }
            pieces.push_back(file.parent_path() / source);
        }
    }
    if (pieces.empty())
    {
        refuse("it names no pieces");
    }
    VtuData joined;
    std::vector<std::string> ragged; // field data whose tuples belong to the points
    for (std::size_t i = 0; i < pieces.size(); ++i)
    {
        VtuData piece = readVtu(pieces[i]);
        if (i == 0)
        {
            joined = std::move(piece);
            for (const auto& [arrayName, array] : joined.fieldData)
            {
                if (joined.pointData.count(arrayName + raggedCountSuffix))
                {
                    ragged.push_back(arrayName);
                }
            }
            continue;
        }
        // The pieces of one output are one level: the same time and step in each (a piece
        // left from another level would restart a mixture, issue 31).
        for (const std::string level : {"TimeValue", "restart:step"})
        {
            const auto first = joined.fieldData.find(level);
            const auto here = piece.fieldData.find(level);
            if ((first == joined.fieldData.end()) != (here == piece.fieldData.end()) ||
                (first != joined.fieldData.end() && first->second.values != here->second.values))
            {
                const auto text = [](const auto& it, const auto& end) {
                    return it == end || it->second.values.empty()
                               ? std::string("none")
                               : formatNumber(it->second.values[0], 17);
                };
                refuse("its pieces are of different levels: " + level + " " +
                       text(first, joined.fieldData.end()) + " in '" + pieces[0].string() +
                       "', " + text(here, piece.fieldData.end()) + " in '" + pieces[i].string() +
                       "'");
            }
        }
        for (const std::string& arrayName : ragged)
        {
            const auto found = piece.fieldData.find(arrayName);
            if (found == piece.fieldData.end())
            {
                refuse("its piece '" + pieces[i].string() + "' has no field data '" + arrayName +
                       "' like the first piece's");
            }
            std::vector<double>& values = joined.fieldData.at(arrayName).values;
            values.insert(values.end(), found->second.values.begin(), found->second.values.end());
        }
        joined.points.insert(joined.points.end(), piece.points.begin(), piece.points.end());
        for (auto& [arrayName, array] : joined.pointData)
        {
            const auto found = piece.pointData.find(arrayName);
            if (found == piece.pointData.end() || found->second.components != array.components)
            {
                refuse("its piece '" + pieces[i].string() + "' has no array '" + arrayName +
                       "' like the first piece's");
            }
            array.values.insert(array.values.end(), found->second.values.begin(),
                                found->second.values.end());
        }
    }
    // Into the order of the whole set.
    const std::size_t n = joined.pointCount();
    const auto ids = joined.pointData.find(orderBy);
    if (ids == joined.pointData.end() || ids->second.components != 1)
    {
        refuse("its pieces have no array '" + orderBy + "'");
    }
    std::vector<std::size_t> at(n, n); // the row that holds point g
    for (std::size_t row = 0; row < n; ++row)
    {
        const double g = ids->second.values[row];
        if (!(g >= 0.0 && g < static_cast<double>(n)) || g != static_cast<double>(static_cast<std::size_t>(g)) ||
            at[static_cast<std::size_t>(g)] != n)
        {
            refuse("its '" + orderBy + "' values do not number the points 0 .. " +
                   std::to_string(n - 1) + " once each");
        }
        at[static_cast<std::size_t>(g)] = row;
    }
    VtuData ordered = joined;
    const auto reorder = [&](const std::vector<double>& from, std::vector<double>& to, std::size_t width) {
        for (std::size_t g = 0; g < n; ++g)
        {
            std::copy(from.begin() + static_cast<long>(at[g] * width),
                      from.begin() + static_cast<long>((at[g] + 1) * width),
                      to.begin() + static_cast<long>(g * width));
        }
    };
    reorder(joined.points, ordered.points, 3);
    for (auto& [arrayName, array] : ordered.pointData)
    {
        reorder(joined.pointData.at(arrayName).values, array.values,
                static_cast<std::size_t>(array.components));
    }
    // Each point's tuples move with it.
    for (const std::string& arrayName : ragged)
    {
        const std::vector<double>& counts = joined.pointData.at(arrayName + raggedCountSuffix).values;
        const VtuArray& from = joined.fieldData.at(arrayName);
        const auto width = static_cast<std::size_t>(std::max(from.components, 1));
        std::vector<std::size_t> first(n + 1, 0); // of each row's tuples
        for (std::size_t row = 0; row < n; ++row)
        {
            const double count = counts[row];
            if (!(count >= 0.0 && count < 1e15) || count != static_cast<double>(static_cast<std::size_t>(count)))
            {
                refuse("its point array '" + arrayName + raggedCountSuffix + "' is not a count");
            }
            first[row + 1] = first[row] + static_cast<std::size_t>(count) * width;
        }
        if (first[n] != from.values.size())
        {
            refuse("its field data '" + arrayName + "' holds " + std::to_string(from.values.size()) +
                   " values, its point array '" + arrayName + raggedCountSuffix + "' counts " +
                   std::to_string(first[n]));
        }
        std::vector<double>& to = ordered.fieldData.at(arrayName).values;
        auto out = to.begin();
        for (std::size_t g = 0; g < n; ++g)
        {
            out = std::copy(from.values.begin() + static_cast<long>(first[at[g]]),
                            from.values.begin() + static_cast<long>(first[at[g] + 1]), out);
        }
    }
    return ordered;
}

} // namespace sph
