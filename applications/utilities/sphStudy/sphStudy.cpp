// sphStudy: speed against error for any case. Reads system/studyDict (see StudyDefinition.hpp
// and README.md), runs every variant of the case in postProcessing/study/runs/<variant>/,
// and writes postProcessing/study/results.csv, results.md, errorVsTime.png and
// errorVsParticles.png. An interrupted study resumes: finished variants are not run again
// (delete postProcessing/study/runs/<variant> to run one again).
#include "StudyMetric.hpp"
#include "StudyReport.hpp"
#include "StudyRunner.hpp"

#include "core/Application.hpp"
#include "core/CaseLock.hpp"
#include "core/CaseDictionaries.hpp"
#include "core/CommandLine.hpp"
#include "core/LibraryLoader.hpp"
#include "core/ModelListing.hpp"
#include "core/Process.hpp"

#include <iostream>

namespace
{

// The argument as a POSIX shell reads it back: plain when safe, else in single quotes.
std::string shellQuoted(const std::string& argument)
{
    if (argument.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                   "0123456789._-+=/:,@%") == std::string::npos)
    {
        return argument;
    }
    std::string quoted = "'";
    for (char c : argument)
    {
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return quoted + "'";
}

int study(int argc, char** argv)
{
    sph::CommandLine commandLine(
        "sphStudy",
        "runs the variants of system/studyDict (e.g. resolution x scheme x Courant number) on "
        "a case and tabulates error against cost: postProcessing/study/results.csv, results.md, "
        "errorVsTime.png, errorVsParticles.png. Metrics: an exactSolution function object, a "
        "summary.json value, a column against a reference variant (a fixed one, or the one that "
        "differs in given levels) or a reference file. An optional 'stable' dictionary of "
        "metric bounds adds a verdict per run. Finished variants are kept: an interrupted study "
        "resumes. -dryRun lists the variants without running them; -listTypes the metric types "
        "and their keys. Keys: see the comment at the top of "
        "applications/utilities/sphStudy/StudyDefinition.hpp and the README.");
    commandLine.enableModelOptions(true, true, true);
    if (!commandLine.parse(argc, argv))
    {
        return 0;
    }
    if (commandLine.listTypes())
    {
        // The metrics are compiled into sphStudy: no model library to load.
        sph::listTypes(std::cout,
                       commandLine.listFamily().empty() ? sph::StudyMetric::family
                                                        : commandLine.listFamily(),
                       commandLine.listFamilyLocation());
        return 0;
    }
    sph::CaseDictionaries dicts(commandLine.caseDir());
    dicts.read({"studyDict"});
    dicts.applySets(commandLine.sets());
    const sph::StudyDefinition definition =
        sph::StudyDefinition::read(dicts.get("studyDict"), commandLine.caseDir());
    const auto variants = definition.variants();
    std::cout << "sphStudy " << sph::projectVersion() << ": " << variants.size() << " variants of "
              << std::filesystem::absolute(definition.baseCase).lexically_normal().string()
              << ", " << definition.repeats << " run(s) each\n";
    if (commandLine.dryRun())
    {
        for (const auto& variant : variants)
        {
            std::cout << "  " << variant.name << ":  sphParticles";
            for (const auto& set : variant.particles)
            {
                std::cout << " -set " << shellQuoted(set);
            }
            std::cout << ";  sphSolid";
            for (const auto& set : variant.solver)
            {
                std::cout << " -set " << shellQuoted(set);
            }
            std::cout << "\n";
        }
        return 0;
    }
    // Stopping the study stops the run under way (gracefully: sphSolid writes its last level)
    // and the study with it; its children die with it even when it is killed (core/Process).
    sph::forwardStopSignals();
    const std::filesystem::path binDir = sph::LibraryLoader::libraryDirectory() / ".." / "bin";
    sph::StudyRunner runner(commandLine.caseDir(), definition, binDir.lexically_normal());
    // One study at a time in a folder: a second would remove the runs of the first
    // (core/CaseLock.hpp; the lock file is postProcessing/study/.sphSolid.lock).
    std::filesystem::create_directories(runner.studyDir());
    const sph::CaseLock lock(runner.studyDir(), "sphStudy");
    if (!lock.takenOver().empty())
    {
        std::cout << "Lock        " << lock.takenOver() << "\n";
    }
    const auto results = runner.run();
    sph::writeStudyReport(runner.studyDir(), definition, results);
    std::cout << "Wrote " << (runner.studyDir() / "results.csv").string() << ", results.md and "
              << "the plots errorVsTime.png, errorVsParticles.png\n";
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    return sph::guardedMain([&] { return study(argc, argv); });
}
