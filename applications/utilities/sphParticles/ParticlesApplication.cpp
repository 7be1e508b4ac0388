#include "sphParticles/ParticlesApplication.hpp"

#include "core/Application.hpp"
#include "core/CaseDictionaries.hpp"
#include "core/CaseLock.hpp"
#include "core/CommandLine.hpp"
#include "core/LibraryLoader.hpp"
#include "core/ModelListing.hpp"
#include "io/AtomicFile.hpp"
#include "solver/CaseSettings.hpp"
#include "solver/ParticleFile.hpp"
#include "solver/ParticleProvenance.hpp"

#include <cstdio>
#include <iostream>

namespace sph
{

int sphParticlesMain(int argc, const char* const* argv)
{
    CommandLine commandLine("sphParticles",
                            "builds the initial particles constant/particles.vtu from "
                            "system/particlesDict");
    commandLine.enableModelOptions(true, true, true);
    if (!commandLine.parse(argc, argv))
    {
        return 0;
    }
    LibraryLoader::loadDefaultLibraries();
    if (commandLine.listTypes())
    {
        listTypes(std::cout, commandLine.listFamily().empty() ? "generator" : commandLine.listFamily(),
                  commandLine.listFamilyLocation());
        return 0;
    }
    CaseDictionaries dicts(commandLine.caseDir());
    dicts.read({"particlesDict", "sphSchemes"});
    dicts.applySets(commandLine.sets());
    const int dimension = readDimension(dicts.get("sphSchemes"));
    InitialParticles particles =
        generateParticles(dicts.get("particlesDict"), dimension, dicts.caseDir());
    // So that sphSolid can tell when particlesDict has changed since (solver/ParticleProvenance).
    recordParticlesDict(particles, dicts.get("particlesDict"), commandLine.sets());
    std::cout << "sphParticles " << projectVersion() << "  (" << commandLine.invocation() << ")\n";
    for (std::size_t b = 0; b < particles.bodyNames.size(); ++b)
    {
        std::size_t count = 0;
        double volume = 0.0;
        for (std::size_t a = 0; a < particles.size(); ++a)
        {
            if (particles.body[a] == static_cast<int>(b))
            {
                ++count;
                volume += particles.V[a];
            }
        }
        char line[256];
        std::snprintf(line, sizeof line, "Body %-12s %8zu particles, total volume %.6e m^%d",
                      particles.bodyNames[b].c_str(), count, volume, dimension);
        std::cout << line << "\n";
    }
    std::cout << "Spacing " << particles.spacing << " m, " << dimension << "D, "
              << particles.size() << " particles\n";
    if (commandLine.dryRun())
    {
        std::cout << "Dry run: system/particlesDict is valid; nothing written.\n";
        return 0;
    }
    // Not while a run reads or writes the case (core/CaseLock.hpp).
    const CaseLock lock(dicts.caseDir(), "sphParticles");
    if (!lock.takenOver().empty())
    {
        std::cout << "Lock        " << lock.takenOver() << "\n";
    }
    const std::filesystem::path file = particleFilePath(dicts.caseDir());
    removeStaleTemporaries(file.parent_path()); // of a run killed while writing (io/AtomicFile)
    writeParticleFile(file, particles);
    std::cout << "Wrote " << file.string() << "\n";
    return 0;
}

} // namespace sph
