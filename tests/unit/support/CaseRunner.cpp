#include "support/CaseRunner.hpp"

#include "core/Process.hpp"

#include "sphParticles/ParticlesApplication.hpp"
#include "sphSolid/SolidApplication.hpp"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <fstream>
#include <regex>
#include <sstream>


namespace sph::test
{

std::filesystem::path sourceDir()
{
    return SPH_SOURCE_DIR;
}

std::filesystem::path copyTutorial(const std::string& relative, const std::filesystem::path& into)
{
    const std::filesystem::path source = sourceDir() / "tutorials" / relative;
    const std::filesystem::path target = into / source.filename();
    std::filesystem::create_directories(target);
    for (const char* folder : {"system", "constant"})
    {
        std::filesystem::copy(source / folder, target / folder,
                              std::filesystem::copy_options::recursive);
    }
    std::error_code ec;
    std::filesystem::remove(target / "constant" / "particles.vtu", ec);
    return target;
}

namespace
{

int runMain(int (*main)(int, const char* const*), const std::string& name,
            const std::filesystem::path& caseDir, const std::vector<std::string>& args)
{
    std::vector<std::string> words{name, "-case", caseDir.string()};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<const char*> argv;
    for (const auto& word : words)
    {
        argv.push_back(word.c_str());
    }
    return main(static_cast<int>(argv.size()), argv.data());
}

} // namespace

int runParticles(const std::filesystem::path& caseDir, const std::vector<std::string>& args)
{
    return runMain(&sphParticlesMain, "sphParticles", caseDir, args);
}

int runSolver(const std::filesystem::path& caseDir, const std::vector<std::string>& args)
{
    return runMain(&sphSolidMain, "sphSolid", caseDir, args);
}

int runProcess(const std::string& app, const std::vector<std::string>& args, std::string* output)
{
    const std::filesystem::path binary = buildDir() / "bin" / app;
    const std::filesystem::path log =
        std::filesystem::temp_directory_path() / ("sphTestOutput_" + std::to_string(::getpid()));
    const int status = runProgram(binary, args, log, {}, "Build the applications first.");
    if (output)
    {
        std::ifstream in(log);
        std::ostringstream text;
        text << in.rdbuf();
        *output = text.str();
    }
    std::filesystem::remove(log);
    return status;
}

std::string fileText(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

double summaryValue(const std::filesystem::path& caseDir, const std::string& path)
{
    std::ifstream in(caseDir / "postProcessing" / "summary.json");
    const nlohmann::json json = nlohmann::json::parse(in);
    const nlohmann::json::json_pointer pointer("/" + path);
    INFO("summary.json has no number at " << path);
    REQUIRE(json.contains(pointer));
    REQUIRE(json.at(pointer).is_number());
    return json.at(pointer).get<double>();
}

Table readTable(const std::filesystem::path& file)
{
    return readDatTable(file);
}

void setEntry(const std::filesystem::path& file, const std::string& key, const std::string& value)
{
    std::ifstream in(file);
    std::ostringstream text;
    text << in.rdbuf();
    std::string content = text.str();
    const std::regex entry("(^|\\n)(\\s*)" + key + "\\s+[^;]*;");
    if (std::regex_search(content, entry))
    {
        content = std::regex_replace(content, entry, "$1$2" + key + " " + value + ";",
                                     std::regex_constants::format_first_only);
    }
    else
    {
        content += "\n" + key + " " + value + ";\n";
    }
    std::ofstream(file) << content;
}

} // namespace sph::test
