#include "StudyRunner.hpp"
#include "StudyMetric.hpp"

#include "core/InputError.hpp"
#include "core/IoError.hpp"
#include "core/Process.hpp"
#include "core/Statistics.hpp"
#include "io/AtomicFile.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>


namespace sph
{

namespace
{

const double notAvailable = std::numeric_limits<double>::quiet_NaN();
const char* nextToStudy = "It is looked for next to sphStudy; rebuild sphSolid.";

// The first line of an error message in a log (the line after the banner).
std::string firstError(const std::filesystem::path& log)
{
    std::ifstream in(log);
    std::string line;
    bool next = false;
    while (std::getline(in, line))
    {
        if (next && !line.empty())
        {
            return line;
        }
        next = line.rfind("--> ", 0) == 0;
    }
    return "see " + log.string();
}

// What a solver exit code without a summary means (core/Application.hpp).
std::string failureKind(int code)
{
    switch (code)
    {
    case 1:
        return "input error";
    default:
        return "error (exit code " + std::to_string(code) + ")";
    }
}

void copyCase(const std::filesystem::path& from, const std::filesystem::path& to)
{
    std::filesystem::create_directories(to);
    for (const char* folder : {"system", "constant"})
    {
        std::filesystem::copy(from / folder, to / folder, std::filesystem::copy_options::recursive);
    }
    std::error_code ec;
    std::filesystem::remove(to / "constant" / "particles.vtu", ec);
}

// An I/O error (exit 4: a full disk, a file-size limit) is not a property of the variant: the
// study stops with it, as the next variants would meet the same disk, and records nothing for
// the variant, so that running the study again (with room on the disk) runs it.
void stopOnIoError(int code, const std::string& program, const std::string& variant,
                   const std::filesystem::path& log)
{
    if (code == 4)
    {
        throw IoError(firstError(log) + "\n(" + program + " of the variant " + variant +
                      ", its log: " + log.string() + ")");
    }
}

} // namespace

StudyRunner::StudyRunner(std::filesystem::path caseDir, const StudyDefinition& study,
                         std::filesystem::path binDir)
    : caseDir_(std::move(caseDir)), study_(study), binDir_(std::move(binDir)),
      studyDir_(caseDir_ / "postProcessing" / "study")
{
}

std::filesystem::path StudyRunner::variantDir(const std::string& name) const
{
    return studyDir_ / "runs" / name;
}

std::vector<VariantResult> StudyRunner::run()
{
    const auto variants = study_.variants();
    std::vector<VariantResult> results;
    const auto start = std::chrono::steady_clock::now();
    removeStaleTemporaries(studyDir_); // of a study killed while writing (io/AtomicFile)
    for (std::size_t i = 0; i < variants.size(); ++i)
    {
        std::cout << "[" << i + 1 << "/" << variants.size() << "] " << variants[i].name << ": "
                  << std::flush;
        VariantResult result = runVariant(variants[i]);
        if (result.status == "finished")
        {
            finished_.insert(result.variant.name);
        }
        computeMetrics(result);
        results.push_back(result);
        std::ostringstream line;
        line.precision(4);
        line << (result.reused ? "done earlier, " : "") << result.status;
        if (result.status == "finished" || result.status == "failed")
        {
            line << ", " << result.wallSeconds << " s, " << result.usPerParticleStep
                 << " us/particle-step";
            for (const auto& metric : study_.metrics)
            {
                line << ", " << metric->name() << " " << result.metrics[metric->name()];
            }
        }
        if (!result.failure.empty())
        {
            line << " (" << result.failure.substr(0, 120) << ")";
        }
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        line << "  [study " << static_cast<long>(elapsed) << " s]";
        std::cout << line.str() << std::endl;
    }
    return results;
}

VariantResult StudyRunner::runVariant(const StudyVariant& variant)
{
    VariantResult result;
    result.variant = variant;
    const std::filesystem::path dir = variantDir(variant.name);
    const std::filesystem::path record = dir / "study.json";
    if (std::filesystem::exists(record))
    {
        std::ifstream in(record);
        const nlohmann::json json = nlohmann::json::parse(in);
        // A number, or `otherwise` when absent or null (not available).
        const auto number = [&json](const char* key, double otherwise) {
            return json.contains(key) && json.at(key).is_number() ? json.at(key).get<double>()
                                                                  : otherwise;
        };
        result.status = json.at("status").get<std::string>();
        result.failure = json.value("failure", "");
        result.particles = number("particles", 0.0);
        result.steps = number("steps", 0.0);
        result.wallSeconds = number("wallSeconds", notAvailable);
        result.usPerParticleStep = number("usPerParticleStep", notAvailable);
        result.peakMemoryMB = number("peakMemoryMB", notAvailable);
        result.reused = true;
        return result;
    }
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
    copyCase(study_.baseCase, dir);

    std::vector<std::string> args{"-case", dir.string()};
    for (const auto& set : variant.particles)
    {
        args.push_back("-set");
        args.push_back(set);
    }
    const int particlesCode =
        runProgram(binDir_ / "sphParticles", args, dir / "log.sphParticles", {}, nextToStudy);
    stopOnIoError(particlesCode, "sphParticles", variant.name, dir / "log.sphParticles");
    if (particlesCode != 0)
    {
        result.status = "failed";
        result.failure = "sphParticles: " + firstError(dir / "log.sphParticles");
    }
    else
    {
        std::vector<std::string> solverArgs{"-case", dir.string()};
        if (study_.threads > 0)
        {
            solverArgs.push_back("-threads");
            solverArgs.push_back(std::to_string(study_.threads));
        }
        for (const auto& set : variant.solver)
        {
            solverArgs.push_back("-set");
            solverArgs.push_back(set);
        }
        std::vector<double> walls;
        std::vector<double> rates;
        for (long r = 0; r < study_.repeats; ++r)
        {
            // A run that stops before its summary (an input or I/O error) must not leave the
            // previous repeat's to be read as its own.
            const std::filesystem::path summary = dir / "postProcessing" / "summary.json";
            std::filesystem::remove(summary, ec);
            const int code = runProgram(binDir_ / "sphSolid", solverArgs, dir / "log.sphSolid", {}, nextToStudy);
            stopOnIoError(code, "sphSolid", variant.name, dir / "log.sphSolid");
            if (code == 1 || !std::filesystem::exists(summary))
            {
                result.status = "failed";
                result.failure = failureKind(code) + ": " + firstError(dir / "log.sphSolid");
                break;
            }
            std::ifstream in(summary);
            const nlohmann::json json = nlohmann::json::parse(in);
            result.status = json.at("status").get<std::string>();
            result.failure = json.value("failure", "");
            result.particles = json.at("particles").get<double>();
            result.steps = json.at("steps").get<double>();
            result.peakMemoryMB =
                std::max(result.peakMemoryMB, json.at("peakMemoryMB").get<double>());
            walls.push_back(json.at("wallSeconds").get<double>());
            rates.push_back(json.at("computeParticleStepsPerSecond").get<double>());
            if (result.status != "finished")
            {
                break; // a failure repeats itself
            }
        }
        result.wallSeconds = median(walls);
        const double rate = median(rates);
        result.usPerParticleStep = rate > 0.0 ? 1e6 / rate : notAvailable;
        const auto newline = result.failure.find('\n');
        if (newline != std::string::npos)
        {
            result.failure.resize(newline);
        }
    }
    nlohmann::ordered_json json; // typed: numbers as numbers, not available as null
    json["variant"] = variant.name;
    json["status"] = result.status;
    json["failure"] = result.failure;
    json["particles"] = result.particles;
    json["steps"] = result.steps;
    json["wallSeconds"] = result.wallSeconds;
    json["usPerParticleStep"] = result.usPerParticleStep;
    json["peakMemoryMB"] = result.peakMemoryMB;
    writeTextAtomically(record, json.dump(4) + "\n");
    return result;
}

void StudyRunner::computeMetrics(VariantResult& result) const
{
    const StudyRun run{result.variant, caseDir_, studyDir_ / "runs", finished_};
    for (const auto& metric : study_.metrics)
    {
        double value = notAvailable;
        try
        {
            value = metric->evaluate(run);
        }
        catch (const MetricDefinitionError&)
        {
            throw; // studyDict is wrong: every run would give nothing
        }
        catch (const std::exception&)
        {
            value = notAvailable; // e.g. a run that failed before writing its tables
        }
        result.metrics[metric->name()] = value;
    }
}

} // namespace sph
