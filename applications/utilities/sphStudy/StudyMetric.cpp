#include "StudyMetric.hpp"

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

namespace pt = boost::property_tree;

namespace sph
{

double summaryValue(const StudyRun& run, const std::string& path)
{
    pt::ptree tree;
    pt::read_json((run.dir() / "postProcessing" / "summary.json").string(), tree);
    return tree.get<double>(pt::ptree::path_type(path, '/'));
}

} // namespace sph
