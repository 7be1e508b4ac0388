#include "sphSolid/SolidApplication.hpp"

#include "core/Application.hpp"
#include "core/CaseDictionaries.hpp"
#include "core/CaseLock.hpp"
#include "core/CommandLine.hpp"
#include "core/InputError.hpp"
#include "core/IoError.hpp"
#include "core/LibraryLoader.hpp"
#include "core/ModelListing.hpp"
#include "parallel/Communicator.hpp"
#include "solver/CaseSettings.hpp"
#include "solver/ParticleFile.hpp"
#include "solver/ParticleProvenance.hpp"
#include "solver/Simulation.hpp"

#include <omp.h>

#include <iostream>
#include <memory>

namespace sph
{

namespace
{

template <int D>
int runDimension(const CaseDictionaries& dicts, const ControlSettings& control,
                 const SchemeSettings& schemes, bool dryRun)
{
    const std::filesystem::path particleFile = particleFilePath(dicts.caseDir());
    InitialParticles initial;
    if (std::filesystem::exists(particleFile))
    {
        initial = readParticleFile(particleFile);
        const std::string made = checkParticlesDict(initial, dicts.caseDir()); // or stale: stop
        std::cout << "Particles   " << made << "\n";
    }
    else if (dryRun && dicts.has("particlesDict"))
    {
        // Without particles yet, a dry run still checks system/particlesDict by building them.
        initial = generateParticles(dicts.get("particlesDict"), D, dicts.caseDir());
    }
    else if (!dicts.has("particlesDict"))
    {
        throw InputError("the case has neither constant/particles.vtu nor system/particlesDict",
                         {"Write system/particlesDict (the bodies' geometry) and run sphParticles; "
                          "see tutorials/ for examples."});
    }
    else
    {
        initial = readParticleFile(particleFile); // reports the missing file
    }
    Simulation<D> simulation(dicts, control, schemes, initial);
    initial = InitialParticles(); // copied into the simulation: not kept for the whole run
    RunLog log(std::cout, 1.0, RunLog::stdoutIsTerminal()); // on a terminal: one line in place
    log.header(simulation.describe());
    if (dryRun)
    {
        simulation.checkSetup();
        log.line("Dry run: every dictionary is valid and every model was built; not running.");
        return 0;
    }
    log.line("");
    simulation.run(log);
    return simulation.stoppedBy().empty() ? 0 : stoppedExitCode; // stopped: restartable
}

// One run per case folder (core/CaseLock.hpp): rank 0 of a distributed run holds the lock, and
// every rank stops with its error.
std::unique_ptr<CaseLock> lockCase(const std::filesystem::path& caseDir, const Communicator& world)
{
    std::unique_ptr<CaseLock> lock;
    std::string refused;
    std::vector<std::string> notes;
    if (world.rank() == 0)
    {
        try
        {
            lock = std::make_unique<CaseLock>(caseDir, "sphSolid");
        }
        catch (const InputError& inUse)
        {
            refused = "I" + inUse.message();
            notes = inUse.notes();
        }
        catch (const IoError& unwritable)
        {
            refused = "O" + std::string(unwritable.what());
        }
    }
    refused = world.broadcast(refused, 0);
    if (refused.rfind("O", 0) == 0)
    {
        throw IoError(refused.substr(1));
    }
    if (!refused.empty())
    {
        throw InputError(refused.substr(1), notes); // rank 0, which has the notes, prints it
    }
    if (lock && !lock->takenOver().empty())
    {
        std::cout << "Lock        " << lock->takenOver() << "\n";
    }
    return lock;
}

} // namespace

int sphSolidMain(int argc, const char* const* argv)
{
    CommandLine commandLine("sphSolid", "SPH for elastic and hyperelastic solids: runs a case");
    commandLine.options().add_options()(
        "threads",
        integerOption("threads", 1, maxThreads,
                      "more threads than cores only slow a run down (this machine has " +
                          std::to_string(omp_get_num_procs()) + ")"),
        "number of OpenMP threads (default: OMP_NUM_THREADS or all cores)")(
        "parallel", "run on the MPI ranks of mpirun (mpirun -np N sphSolid -parallel)");
    if (!commandLine.parse(argc, argv))
    {
        return 0;
    }
    if (commandLine.values().count("threads"))
    {
        omp_set_num_threads(static_cast<int>(commandLine.values()["threads"].as<long>()));
    }
    LibraryLoader::loadDefaultLibraries();
    const std::filesystem::path caseDir = commandLine.caseDir();

    if (commandLine.listTypes())
    {
        // A case's own libraries show up in the listing too.
        if (std::filesystem::exists(caseDir / "system" / "controlDict"))
        {
            CaseDictionaries dicts(caseDir);
            dicts.read({"controlDict"});
            loadCaseLibraries(ControlSettings::read(dicts), caseDir);
        }
        listTypes(std::cout, commandLine.listFamily(), commandLine.listFamilyLocation());
        return 0;
    }

    const bool parallel = commandLine.values().count("parallel") > 0;
    if (!parallel && launchedRanks() > 1)
    {
        throw InputError("sphSolid is one of " + std::to_string(launchedRanks()) +
                             " processes mpirun started, without -parallel: each would run the "
                             "whole case alone, over the same files",
                         {"A distributed run: mpirun -np " + std::to_string(launchedRanks()) +
                              " sphSolid -parallel. A serial run: sphSolid, without mpirun."});
    }
    CaseDictionaries dicts(caseDir);
    dicts.read({"controlDict", "sphSchemes", "bodies"}, {"particlesDict", "walls"});
    // particlesDict is sphParticles' input; sphSolid reads it only to check the particles.
    dicts.applySets(commandLine.sets(), {"particlesDict"});
    std::cout << "sphSolid " << projectVersion() << "  (" << commandLine.invocation() << ")\n"
              << "Threads     " << omp_get_max_threads() << "\n";
    if (parallel)
    {
        std::cout << "Ranks       " << Communicator::world().size() << "\n";
    }
    const std::unique_ptr<CaseLock> lock =
        commandLine.dryRun() ? nullptr : lockCase(dicts.caseDir(), Communicator::world());
    const ControlSettings control = ControlSettings::read(dicts);
    loadCaseLibraries(control, dicts.caseDir());
    const SchemeSettings schemes = SchemeSettings::read(dicts.get("sphSchemes"));
    switch (schemes.dimension)
    {
    case 1:
        return runDimension<1>(dicts, control, schemes, commandLine.dryRun());
    case 2:
        return runDimension<2>(dicts, control, schemes, commandLine.dryRun());
    default:
        return runDimension<3>(dicts, control, schemes, commandLine.dryRun());
    }
}

} // namespace sph
