#pragma once
// constant/particles.vtu: the initial particles written by sphParticles and read by sphSolid.
// A VTK point set (open it in ParaView to check the geometry) with point arrays `volume` and
// `bodyId`, and field data `bodyNames`, `spacing`, `dimension`, and what made it (sphParticles):
// `particlesDict` (its canonical lines) and `particlesDictSets`
// (solver/ParticleProvenance).

#include "core/Dictionary.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sph
{

struct InitialParticles
{
    int dimension = 0;
    double spacing = 0.0;
    std::vector<std::string> bodyNames;
    std::vector<double> X;    // 3 per particle (zeros beyond the dimension)
    std::vector<double> V;    // volume per particle
    std::vector<int> body;    // index into bodyNames; each body's particles are contiguous
    // What made them: system/particlesDict as sphParticles used it (after its -set) in canonical
    // form (core/CanonicalDictionary) and those -set arguments. Empty in files written by older
    // versions or other tools.
    std::vector<std::string> particlesDictLines;
    std::vector<std::string> particlesDictSets;

    std::size_t size() const { return V.size(); }
};

void writeParticleFile(const std::filesystem::path& file, const InitialParticles& particles);
InitialParticles readParticleFile(const std::filesystem::path& file);

// Builds the particles of every body of system/particlesDict with its generator.
InitialParticles generateParticles(const Dictionary& particlesDict, int dimension,
                                   const std::filesystem::path& caseDir);

std::filesystem::path particleFilePath(const std::filesystem::path& caseDir);

} // namespace sph
