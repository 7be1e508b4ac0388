#include "StudyMetric.hpp"

#include "core/InputError.hpp"

#include <nlohmann/json.hpp>

#include <fstream>

namespace sph
{

double summaryValue(const StudyRun& run, const std::string& path)
{
    const std::filesystem::path file = run.dir() / "postProcessing" / "summary.json";
    std::ifstream in(file);
    const nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
    const nlohmann::json::json_pointer pointer("/" + path);
    if (json.is_discarded() || !json.contains(pointer) || !json.at(pointer).is_number())
    {
        throw InputError("'" + file.string() + "' has no number at '" + path + "'");
    }
    return json.at(pointer).get<double>();
}

} // namespace sph
