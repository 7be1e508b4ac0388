#pragma once
// Which system/particlesDict made constant/particles.vtu. sphParticles records it in the file:
// the dictionary as it used it (after its -set) in canonical form and those -set arguments. sphSolid reads the case's particlesDict again, applies the same -set, and
// refuses particles made from something else: an edit of particlesDict without running
// sphParticles again would otherwise run the old particles without a word.

#include "core/Dictionary.hpp"
#include "solver/ParticleFile.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sph
{

// sphParticles: what made the particles (particlesDict after `sets` were applied to it).
void recordParticlesDict(InitialParticles& particles, const Dictionary& particlesDict,
                         const std::vector<std::string>& sets);

// sphSolid: an InputError at the first entry that changed when the case's system/particlesDict
// (with the recorded -set) no longer makes these particles; otherwise one line for the log on
// what made them. Files without a record (older versions, other tools) are run, with a note.
std::string checkParticlesDict(const InitialParticles& particles,
                               const std::filesystem::path& caseDir);

} // namespace sph
