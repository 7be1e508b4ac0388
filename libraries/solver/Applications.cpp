#include "solver/Applications.hpp"

#include "core/Application.hpp"
#include "core/CaseDictionaries.hpp"
#include "core/CommandLine.hpp"
#include "core/InputError.hpp"
#include "core/LibraryLoader.hpp"
#include "core/Registry.hpp"
#include "core/Suggest.hpp"
#include "solver/CaseSettings.hpp"
#include "solver/ParticleFile.hpp"
#include "solver/Simulation.hpp"

#include <omp.h>

#include <cstdio>
#include <iostream>

namespace sph
{

void listTypes(std::ostream& out, const std::string& family, const SourceLocation& where)
{
    RegistryStore& store = RegistryStore::instance();
    const std::vector<std::string> families = store.families();
    if (!family.empty() && std::find(families.begin(), families.end(), family) == families.end())
    {
        std::vector<std::string> notes{"Families: " + joinSorted(families)};
        const std::string hint = didYouMean(family, families);
        if (!hint.empty())
        {
            notes.push_back(hint);
        }
        throw InputError(where, "-listTypes: unknown family '" + family + "'", notes);
    }
    for (const std::string& name : families)
    {
        if (!family.empty() && name != family)
        {
            continue;
        }
        const auto models = store.names(name);
        out << name << " (" << models.size() << " type" << (models.size() == 1 ? "" : "s")
            << ")\n";
        for (const std::string& model : models)
        {
            const ModelRecord* record = store.find(name, model);
            std::string dims;
            for (int d : record->dimensions())
            {
                dims += d == 0 ? "any" : std::to_string(d) + "D ";
            }
            out << "  " << model << "\n      " << record->description << "\n      ["
                << std::filesystem::path(record->library).filename().string() << ", "
                << (dims == "1D 2D 3D " ? "1D/2D/3D" : dims) << "]\n";
            const auto keys = record->schema().describe();
            if (keys.empty())
            {
                out << "      keys: none\n";
            }
            for (const auto& key : keys)
            {
                out << "      " << key << "\n";
            }
            if (!record->fields.empty())
            {
                out << "      per-particle fields (written to VTK/ as described in the README):\n";
            }
            for (const auto& field : record->fields)
            {
                out << "        " << field.describe() << "\n";
            }
        }
        out << "\n";
    }
}

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
    RunLog log(std::cout);
    log.header(simulation.describe());
    if (dryRun)
    {
        log.line("Dry run: every dictionary is valid and every model was built; not running.");
        return 0;
    }
    log.line("");
    simulation.run(log);
    return 0;
}

} // namespace

int sphSolidMain(int argc, const char* const* argv)
{
    CommandLine commandLine("sphSolid", "SPH for elastic and hyperelastic solids: runs a case");
    commandLine.options().add_options()(
        "threads", boost::program_options::value<int>()->value_name("N"),
        "number of OpenMP threads (default: OMP_NUM_THREADS or all cores)");
    if (!commandLine.parse(argc, argv))
    {
        return 0;
    }
    if (commandLine.values().count("threads"))
    {
        const int threads = commandLine.values()["threads"].as<int>();
        if (threads < 1)
        {
            throw InputError("-threads must be at least 1 (got " + std::to_string(threads) + ")");
        }
        omp_set_num_threads(threads);
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
            ControlSettings::read(dicts);
        }
        listTypes(std::cout, commandLine.listFamily(), commandLine.listFamilyLocation());
        return 0;
    }

    CaseDictionaries dicts(caseDir);
    dicts.read({"controlDict", "sphSchemes", "bodies"}, {"particlesDict"});
    dicts.applySets(commandLine.sets());
    std::cout << "sphSolid " << projectVersion() << "  (" << commandLine.invocation() << ")\n"
              << "Threads     " << omp_get_max_threads() << "\n";
    const ControlSettings control = ControlSettings::read(dicts);
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
    const InitialParticles particles =
        generateParticles(dicts.get("particlesDict"), dimension, dicts.caseDir());
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
    const std::filesystem::path file = particleFilePath(dicts.caseDir());
    writeParticleFile(file, particles);
    std::cout << "Wrote " << file.string() << "\n";
    return 0;
}

} // namespace sph
