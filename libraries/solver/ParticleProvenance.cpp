#include "solver/ParticleProvenance.hpp"

#include "core/CaseDictionaries.hpp"
#include "core/CanonicalDictionary.hpp"
#include "core/InputError.hpp"

#include <map>

namespace sph
{

namespace
{

std::string setsText(const std::vector<std::string>& sets)
{
    std::string text;
    for (const auto& set : sets)
    {
        text += " -set " + set;
    }
    return text;
}

// The notes of every stale-particles error: what to do, and why sphSolid does not do it itself.
std::vector<std::string> staleNotes(const InitialParticles& particles)
{
    std::vector<std::string> notes;
    if (!particles.particlesDictSets.empty())
    {
        notes.push_back("They were made by sphParticles" + setsText(particles.particlesDictSets) +
                        ".");
    }
    notes.push_back(
        "Run sphParticles (it rebuilds constant/particles.vtu from system/particlesDict "
        "as it is now), then sphSolid.");
    notes.push_back("sphSolid does not rebuild them itself: a run uses the particles of "
                    "constant/particles.vtu, the ones you can open and check in ParaView.");
    return notes;
}

} // namespace

void recordParticlesDict(InitialParticles& particles, const Dictionary& particlesDict,
                         const std::vector<std::string>& sets)
{
    particles.particlesDictLines = canonicalLines(particlesDict);
    particles.particlesDictSets = sets;
}

std::string checkParticlesDict(const InitialParticles& particles,
                               const std::filesystem::path& caseDir)
{
    if (particles.particlesDictLines.empty())
    {
        return "constant/particles.vtu does not record its system/particlesDict (an older "
               "sphParticles or another tool): not checked";
    }
    if (!std::filesystem::exists(caseDir / CaseDictionaries::relativePath("particlesDict")))
    {
        return "made by sphParticles; the case has no system/particlesDict to check them against";
    }
    // The dictionary as sphParticles would read it now: the case's files and the same -set.
    CaseDictionaries dicts(caseDir);
    dicts.read({"particlesDict"}, {"sphSchemes"});
    const Dictionary& dict = dicts.get("particlesDict");
    try
    {
        dicts.applySets(particles.particlesDictSets);
    }
    catch (const InputError& error)
    {
        std::vector<std::string> notes{"That -set: " + error.message()};
        for (const auto& note : staleNotes(particles))
        {
            notes.push_back(note);
        }
        throw InputError(dict.location(),
                         "constant/particles.vtu is stale: the -set it was made with no longer "
                         "applies to system/particlesDict",
                         notes);
    }
    const std::vector<CanonicalEntry> entries = canonicalEntries(dict);
    std::vector<std::string> lines;
    for (const auto& entry : entries)
    {
        lines.push_back(entry.line());
    }
    if (lines == particles.particlesDictLines)
    {
        return "made from system/particlesDict as it is" +
               (particles.particlesDictSets.empty()
                    ? std::string()
                    : ", by sphParticles" + setsText(particles.particlesDictSets));
    }

    // Stale: say where, from the recorded canonical lines ("path value").
    std::map<std::string, std::string> before;
    for (const auto& line : particles.particlesDictLines)
    {
        const std::size_t space = line.find(' ');
        before[line.substr(0, space)] = space == std::string::npos ? "" : line.substr(space + 1);
    }
    SourceLocation where = dict.location();
    std::string what = "the order of its entries has changed";
    bool found = false;
    std::map<std::string, bool> now;
    for (const auto& entry : entries)
    {
        now[entry.path] = true;
        const auto old = before.find(entry.path);
        if (old == before.end())
        {
            where = entry.where;
            what = "'" + entry.path + "' is new";
            found = true;
            break;
        }
        if (old->second != entry.value)
        {
            where = entry.where;
            what = "'" + entry.path + "' is " + entry.value + " but was " + old->second;
            found = true;
            break;
        }
    }
    if (!found)
    {
        for (const auto& [path, value] : before)
        {
            if (!now.count(path))
            {
                what = "'" + path + "' (" + value + ") is gone";
                break;
            }
        }
    }
    throw InputError(where,
                     "constant/particles.vtu is stale: " + what +
                         " since sphParticles made it from system/particlesDict",
                     staleNotes(particles));
}

} // namespace sph
