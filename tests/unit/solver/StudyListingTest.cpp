// sphStudy's listings: the metric types in -listTypes, and every shipped studyDict read with
// its variants listed (-dryRun).
#include "support/CaseRunner.hpp"

#include <fstream>
#include <map>
#include <sstream>

using namespace sph::test;
namespace fs = std::filesystem;

TEST_CASE("sphStudy -listTypes lists the metric types with their keys", "[study]")
{
    const std::vector<std::vector<std::string>> calls{{"-listTypes", "studyMetric"},
                                                      {"-listTypes"}};
    for (const auto& args : calls)
    {
        std::string output;
        REQUIRE(runProcess("sphStudy", args, &output) == 0);
        INFO(output);
        CHECK_THAT(output, Catch::Contains("studyMetric (4 types)"));
        // Each type, then its description, origin and keys (name, type, default or required).
        const std::vector<std::pair<std::string, std::vector<std::string>>> types{
            {"exactSolution", {"functionObject  (word, required)",
                               "value  (string, default relativeLinfError)"}},
            {"referenceFile", {"file  (string, required)", "column  (word, required)",
                               "norm  (word, default max, one of: max mean rms)",
                               "scale  (real, optional", "reference  (string, required)",
                               "referenceColumn  (string, required)"}},
            {"referenceVariant", {"file  (string, required)", "column  (word, required)",
                                  "norm  (word, default max", "scale  (real, optional",
                                  "variant  (word, optional)",
                                  "referenceLevels  (dictionary, optional)"}},
            {"summary", {"value  (string, required)"}}};
        // The listing by type: "  name" starts an entry, its lines are indented further.
        std::map<std::string, std::string> entries;
        std::string current;
        std::istringstream lines(output);
        for (std::string line; std::getline(lines, line);)
        {
            if (line.size() > 2 && line.compare(0, 2, "  ") == 0 && line[2] != ' ')
            {
                current = line.substr(2);
            }
            else if (!current.empty())
            {
                entries[current] += line + "\n";
            }
        }
        CHECK(entries.size() == types.size());
        for (const auto& [type, keys] : types)
        {
            const std::string& entry = entries[type];
            CHECK_THAT(entry, Catch::Contains("[sphStudy, any]"));
            for (const auto& key : keys)
            {
                CHECK_THAT(entry, Catch::Contains("      " + key));
            }
        }
    }
}

TEST_CASE("the shipped studies read and list their variants", "[study]")
{
    // Every tutorial's system/studyDict, in place (-dryRun writes nothing).
    const std::map<std::string, std::string> expected{
        {"bar1D/schemeComparison", "22 variants of " +
                                       (sourceDir() / "tutorials/bar1D/dykaBar").string()},
        {"rings2D/schemeComparison",
         "7 variants of " + (sourceDir() / "tutorials/rings2D/collidingRings").string()}};
    std::size_t studies = 0;
    for (auto it = fs::recursive_directory_iterator(sourceDir() / "tutorials");
         it != fs::recursive_directory_iterator(); ++it)
    {
        if (it->path().filename() == "postProcessing")
        {
            it.disable_recursion_pending(); // the runs of a study made in the source tree
            continue;
        }
        if (it->path().filename() != "studyDict")
        {
            continue;
        }
        const fs::path caseDir = it->path().parent_path().parent_path();
        std::string output;
        CHECK(runProcess("sphStudy", {"-case", caseDir.string(), "-dryRun"}, &output) == 0);
        INFO(output);
        const std::string name = fs::relative(caseDir, sourceDir() / "tutorials").string();
        if (expected.count(name))
        {
            CHECK_THAT(output, Catch::Contains(expected.at(name)));
        }
        ++studies;
    }
    CHECK(studies >= 10);
}
