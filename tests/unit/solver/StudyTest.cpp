// sphStudy end to end on a short Dyka bar: variants, metrics of every kind, references first,
// resume, report files, errors in studyDict (StudyListingTest.cpp: -listTypes, the shipped
// studies).
#include "support/CaseRunner.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <sstream>

using namespace sph::test;
namespace fs = std::filesystem;

namespace
{

const char* studyDict = R"(
common { solver ("endTime=1e-3" "writeInterval=1"); }
axes
{
    resolution { n20 { particles ("bar.n=20"); } n40 { particles ("bar.n=40"); } }
    scheme
    {
        TLnone  { solver ("formulation.type=totalLagrangian" "stabilisation.type=none"); }
        ULgradF { solver ("formulation.type=updatedLagrangian" "stabilisation.type=gradF"); }
    }
}
threads 1;
metrics
{
    tipError    { type exactSolution; functionObject tipError; }
    energyDrift { type summary; value functions/energy/maxDrift; }
    // The drift shifted by two spacings, relative to 0.5 (the footprint's error form).
    shiftedDrift { type summary; value functions/energy/maxDrift; plusSpacings 2; reference 0.5; }
    // Each variant against the 40-particle run of its own scheme, in units of 1 mm.
    selfConvergence
    {
        type            referenceVariant;
        referenceLevels { resolution n40; }
        file            postProcessing/tipError/tipError.dat;
        column          u_numeric;
        scale           1e-3;
    }
    againstOne
    {
        type    referenceVariant;
        variant n40_TLnone;
        file    postProcessing/tipError/tipError.dat;
        column  u_numeric;
    }
    // Against a hand-written table of zeros (no header): the largest |u| in mm.
    largestTip
    {
        type            referenceFile;
        file            postProcessing/tipError/tipError.dat;
        column          u_numeric;
        reference       "zeros.dat";
        referenceColumn "2";            // a number in quotes: a string key
        scale           1e-3;
    }
    // The same, its mean (norm mean: |mean of the difference|, a plateau's offset).
    meanTip
    {
        type            referenceFile;
        file            postProcessing/tipError/tipError.dat;
        column          u_numeric;
        reference       "zeros.dat";
        referenceColumn "2";
        norm            mean;
        scale           1e-3;
    }
}
plot { groupBy scheme; along resolution; }
stable { selfConvergence { max 1e-3; } }    // only the reference resolution passes
)";

// results.csv as rows of name -> value.
std::vector<std::map<std::string, std::string>> readCsv(const fs::path& file)
{
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header;
    std::stringstream names(line);
    for (std::string name; std::getline(names, name, ',');)
    {
        header.push_back(name);
    }
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line))
    {
        std::stringstream cells(line);
        std::map<std::string, std::string> row;
        std::string cell;
        for (std::size_t c = 0; c < header.size() && std::getline(cells, cell, ','); ++c)
        {
            row[header[c]] = cell;
        }
        rows.push_back(row);
    }
    return rows;
}

} // namespace

TEST_CASE("sphStudy runs every variant, measures, reports and resumes", "[study]")
{
    TempDir dir;
    // A case path that would break out of a quoted shell command: nothing goes through a shell
    // (gnuplot is started with an argument vector in the study folder), so the plots appear
    // and no command runs.
    const fs::path hostile = dir.path() / "it's $(touch hacked) a case";
    fs::create_directories(hostile);
    const fs::path caseDir = copyTutorial("bar1D/dykaBar", hostile);
    std::ofstream(caseDir / "system" / "studyDict") << studyDict;
    std::ofstream(caseDir / "zeros.dat") << "0 0\n1 0\n";

    std::string output;
    REQUIRE(runProcess("sphStudy", {"-case", caseDir.string()}, &output) == 0);
    INFO(output);
    // The variants compared with others run first: n40_TLnone (both metrics), n40_ULgradF.
    const auto first = output.find("[1/4] n40_TLnone");
    const auto second = output.find("[2/4] n40_ULgradF");
    CHECK(first != std::string::npos);
    CHECK(second != std::string::npos);

    const fs::path study = caseDir / "postProcessing" / "study";
    for (const char* file : {"results.csv", "results.md", "study.gp", "errorVsTime.png",
                             "errorVsParticles.png"})
    {
        CHECK(fs::exists(study / file));
    }
    CHECK_FALSE(fs::exists(dir.path() / "hacked"));
    CHECK_FALSE(fs::exists(study / "hacked"));
    const auto rows = readCsv(study / "results.csv");
    REQUIRE(rows.size() == 4);
    for (const auto& row : rows)
    {
        INFO(row.at("variant"));
        CHECK(row.at("status") == "finished");
        CHECK(std::stod(row.at("particles")) == (row.at("resolution") == "n20" ? 20 : 40));
        CHECK(std::stod(row.at("usPerParticleStep")) > 0.0);
        const double tipError = std::stod(row.at("tipError"));
        CHECK(tipError > 0.0);
        CHECK(tipError < 1.0);
        CHECK(std::stod(row.at("energyDrift")) < 1e-2);
        {
            std::ifstream in(study / "runs" / row.at("variant") / "postProcessing/summary.json");
            const auto summary = nlohmann::json::parse(in);
            const double drift = summary.at("functions").at("energy").at("maxDrift");
            const double spacing = summary.at("spacing");
            CHECK(spacing > 0.0);
            CHECK(std::stod(row.at("shiftedDrift")) ==
                  Approx(std::abs(drift + 2.0 * spacing - 0.5) / 0.5).epsilon(1e-8));
        }
        const double self = std::stod(row.at("selfConvergence"));
        if (row.at("resolution") == "n40")
        {
            CHECK(self == 0.0); // its own reference
        }
        else
        {
            // 20 against 40 particles: differences of a fraction of the 0.94 mm amplitude.
            CHECK(self > 1e-3);
            CHECK(self < 0.94);
        }
        CHECK((std::stod(row.at("againstOne")) == 0.0) == (row.at("variant") == "n40_TLnone"));
        double largest = 0.0;
        double sum = 0.0;
        const auto tip = readTable(study / "runs" / row.at("variant") /
                                   "postProcessing/tipError/tipError.dat")
                             .column("u_numeric");
        for (double u : tip)
        {
            largest = std::max(largest, std::abs(u));
            sum += u;
        }
        CHECK(std::stod(row.at("largestTip")) == Approx(largest / 1e-3).epsilon(1e-8));
        const double mean = std::abs(sum / static_cast<double>(tip.size())) / 1e-3;
        CHECK(mean > 0.0);
        CHECK(mean < largest / 1e-3); // the bar's tip swings both ways
        CHECK(std::stod(row.at("meanTip")) == Approx(mean).epsilon(1e-6));
        if (row.at("resolution") == "n40")
        {
            CHECK(row.at("verdict") == "pass"); // RFC 4180: quoted only when needed
        }
        else
        {
            CHECK_THAT(row.at("verdict"), Catch::Contains("fail: selfConvergence"));
        }
    }
    std::stringstream markdown;
    markdown << std::ifstream(study / "results.md").rdbuf();
    CHECK_THAT(markdown.str(),
               Catch::Contains("- ULgradF: passes in 1 of 2 runs; not: n20_ULgradF"));
    CHECK_THAT(markdown.str(), Catch::Contains("**Best tipError for the wall time**"));

    // A second run reuses every finished variant.
    REQUIRE(runProcess("sphStudy", {"-case", caseDir.string()}, &output) == 0);
    std::size_t reused = 0;
    for (auto at = output.find("done earlier"); at != std::string::npos;
         at = output.find("done earlier", at + 1))
    {
        ++reused;
    }
    CHECK(reused == 4);
}

TEST_CASE("sphStudy reports mistakes in studyDict at their place", "[study][errors]")
{
    TempDir dir;
    const fs::path caseDir = copyTutorial("bar1D/dykaBar", dir.path());
    std::ofstream(caseDir / "zeros.dat") << "0 0\n1 0\n"; // read when studyDict is read
    // The output of `sphStudy -dryRun` on studyDict with `wrong` replaced by `edit`; exit code 1.
    const auto dryRunWith = [&](const std::string& wrong, const std::string& edit)
    {
        std::string text = studyDict;
        const auto at = text.find(wrong);
        REQUIRE(at != std::string::npos);
        text.replace(at, wrong.size(), edit);
        std::ofstream(caseDir / "system" / "studyDict") << text;
        std::string output;
        CHECK(runProcess("sphStudy", {"-case", caseDir.string(), "-dryRun"}, &output) == 1);
        return output;
    };
    SECTION("a reference level that does not exist")
    {
        const std::string output = dryRunWith("resolution n40;", "resolution n80;");
        CHECK_THAT(output, Catch::Contains("system/studyDict:"));
        CHECK_THAT(output, Catch::Contains("axis 'resolution' has no level 'n80'"));
        CHECK_THAT(output, Catch::Contains("Levels: n20, n40"));
    }
    SECTION("both a variant and reference levels")
    {
        const std::string output = dryRunWith(
            "variant n40_TLnone;", "variant n40_TLnone; referenceLevels { scheme TLnone; }");
        CHECK_THAT(output, Catch::Contains("needs either 'variant' or 'referenceLevels'"));
    }
    SECTION("an unknown reference variant")
    {
        const std::string output = dryRunWith("variant n40_TLnone;", "variant n40_TLnon;");
        CHECK_THAT(output, Catch::Contains("no variant 'n40_TLnon'"));
        CHECK_THAT(output, Catch::Contains("Did you mean 'n40_TLnone'?"));
    }
    SECTION("a stability bound on a metric that does not exist")
    {
        const std::string output =
            dryRunWith("stable { selfConvergence", "stable { selfConvergenc");
        CHECK_THAT(output, Catch::Contains("stable: 'selfConvergenc' must be one of the metrics"));
        CHECK_THAT(output, Catch::Contains("Did you mean 'selfConvergence'?"));
    }
    SECTION("a summary's reference of zero")
    {
        const std::string output = dryRunWith("reference 0.5;", "reference 0;");
        CHECK_THAT(output, Catch::Contains("system/studyDict:"));
        CHECK_THAT(output, Catch::Contains("must be a finite number other than 0"));
        CHECK_THAT(output, Catch::Contains("hint: leave `reference` out"));
    }
    SECTION("an unknown metric type")
    {
        const std::string output = dryRunWith("type summary;", "type sumary;");
        CHECK_THAT(output, Catch::Contains("unknown studyMetric type 'sumary'"));
        CHECK_THAT(output, Catch::Contains("Valid studyMetric types (4): exactSolution, "
                                           "referenceFile, referenceVariant, summary"));
        CHECK_THAT(output, Catch::Contains("Did you mean 'summary'?"));
        // sphStudy loads no case libraries: no hint about controlDict's libs.
        CHECK_THAT(output, !Catch::Contains("libs"));
    }
    SECTION("a key of another metric type")
    {
        const std::string output =
            dryRunWith("functionObject tipError; }", "functionObject tipError; norm rms; }");
        CHECK_THAT(output, Catch::Contains("unknown key 'norm' in 'metrics/tipError'"));
        CHECK_THAT(output, Catch::Contains("exactSolution accepts: functionObject, type, value"));
    }
    SECTION("a metric without a key its type needs")
    {
        const std::string output = dryRunWith("reference       \"zeros.dat\";", "");
        CHECK_THAT(output, Catch::Contains("missing required key 'reference' in "
                                           "'metrics/largestTip'"));
        CHECK_THAT(output, Catch::Contains("referenceFile needs:"));
    }
    SECTION("a level name that would leave the study folder")
    {
        const std::string output = dryRunWith("n20 { particles", "../../escape { particles");
        CHECK_THAT(output, Catch::Contains("system/studyDict:"));
        CHECK_THAT(output, Catch::Contains("level '../../escape' is not a plain name"));
        CHECK_THAT(output, Catch::Contains("letters, digits and _ . + -"));
    }
    SECTION("a level name with a quote (gnuplot script text)")
    {
        const std::string output = dryRunWith("n20 { particles", "n20'`id` { particles");
        CHECK_THAT(output, Catch::Contains("is not a plain name"));
    }
    SECTION("an axis name with a slash")
    {
        CHECK_THAT(dryRunWith("resolution { n20", "/tmp/x { n20"),
                   Catch::Contains("axis '/tmp/x' is not a plain name"));
    }
    SECTION("a stability bound that is not a dictionary")
    {
        const std::string output = dryRunWith("stable { selfConvergence { max 1e-3; } }",
                                              "stable { selfConvergence 1e-3; }");
        CHECK_THAT(output, Catch::Contains("system/studyDict:"));
        CHECK_THAT(output, Catch::Contains("the bounds of 'selfConvergence' must be a dictionary"));
    }
}

namespace
{

// A study of ../dykaBar from a folder of its own, with a level combined with only one scheme.
const char* baseCaseStudy = R"(
baseCase "../dykaBar";
common { solver ("endTime=2e-4" "writeInterval=1"); }
axes
{
    scheme
    {
        TLnone  { solver ("formulation.type=totalLagrangian" "stabilisation.type=none"); }
        ULgradF { solver ("formulation.type=updatedLagrangian" "stabilisation.type=gradF"); }
    }
    resolution
    {
        n20 { particles ("bar.n=20"); }
        n40 { particles ("bar.n=40"); only { scheme (ULgradF); } }
    }
}
threads 1;
metrics { tipError { type exactSolution; functionObject tipError; } }
rank no;
)";

} // namespace

TEST_CASE("sphStudy runs a study of another case, levels combined only with some others",
          "[study]")
{
    TempDir dir;
    const fs::path base = copyTutorial("bar1D/dykaBar", dir.path());
    const fs::path caseDir = dir.path() / "comparison";
    fs::create_directories(caseDir / "system");
    const auto writeStudy = [&](const std::string& wrong = "", const std::string& edit = "")
    {
        std::string text = baseCaseStudy;
        if (!wrong.empty())
        {
            const auto at = text.find(wrong);
            REQUIRE(at != std::string::npos);
            text.replace(at, wrong.size(), edit);
        }
        std::ofstream(caseDir / "system" / "studyDict") << text;
    };
    writeStudy();
    std::string output;
    REQUIRE(runProcess("sphStudy", {"-case", caseDir.string()}, &output) == 0);
    INFO(output);
    CHECK_THAT(output, Catch::Contains("3 variants of " + base.string()));
    const auto rows = readCsv(caseDir / "postProcessing" / "study" / "results.csv");
    REQUIRE(rows.size() == 3);
    std::vector<std::string> names;
    for (const auto& row : rows)
    {
        names.push_back(row.at("variant"));
        CHECK(row.at("status") == "finished");
        CHECK(std::stod(row.at("particles")) == (row.at("resolution") == "n20" ? 20 : 40));
    }
    CHECK(names == std::vector<std::string>{"TLnone_n20", "ULgradF_n20", "ULgradF_n40"});
    // The runs are copies of the base case, made in the study's folder; the base is untouched.
    CHECK(fs::exists(caseDir / "postProcessing/study/runs/ULgradF_n40/system/controlDict"));
    CHECK_FALSE(fs::exists(base / "postProcessing"));

    // Mistakes in baseCase and only, reported at their place by -dryRun (exit code 1).
    const auto dryRunWith = [&](const std::string& wrong, const std::string& edit)
    {
        writeStudy(wrong, edit);
        std::string text;
        CHECK(runProcess("sphStudy", {"-case", caseDir.string(), "-dryRun"}, &text) == 1);
        CHECK_THAT(text, Catch::Contains("system/studyDict:"));
        return text;
    };
    CHECK_THAT(dryRunWith("\"../dykaBar\"", "\"../dykaBra\""),
               Catch::Contains("no case at '" + (dir.path() / "dykaBra").string() + "'"));
    std::string text = dryRunWith("only { scheme", "only { schem");
    CHECK_THAT(text, Catch::Contains("only: no axis 'schem'"));
    CHECK_THAT(text, Catch::Contains("Did you mean 'scheme'?"));
    text = dryRunWith("(ULgradF); }", "(ULgradf2); }");
    CHECK_THAT(text, Catch::Contains("only: axis 'scheme' has no level 'ULgradf2'"));
    CHECK_THAT(text, Catch::Contains("Levels: TLnone, ULgradF"));
    CHECK_THAT(dryRunWith("only { scheme (ULgradF); }", "only { resolution (n20); }"),
               Catch::Contains("only: 'resolution' is this level's own axis"));
    CHECK_THAT(dryRunWith("ULgradF { solver", "ULgradF { only { resolution (n20); } solver"),
               Catch::Contains("level 'n40' of axis 'resolution' is in no variant"));
    CHECK_THAT(dryRunWith("tipError { type exactSolution; functionObject tipError; }",
                          "drift { type referenceVariant; referenceLevels { resolution n40; } "
                          "file postProcessing/energy/energy.dat; column drift; }"),
               Catch::Contains("metric 'drift' compares TLnone_n20 with TLnone_n40, which is "
                               "not a variant"));
}
