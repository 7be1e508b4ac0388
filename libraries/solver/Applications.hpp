#pragma once
// The bodies of the sphSolid applications, callable from tests and other tools:
//   sphSolid      read a case, build every model by name, run (or -dryRun)
//   sphParticles  build constant/particles.vtu from system/particlesDict
// Each returns the process exit code; errors propagate as exceptions (see Application.hpp).

#include "core/SourceLocation.hpp"

#include <iosfwd>
#include <string>

namespace sph
{

int sphSolidMain(int argc, const char* const* argv);
int sphParticlesMain(int argc, const char* const* argv);

// -listTypes: every registered model of every family (or one family) with description and keys.
// `where`: where the family name was typed (for the error on an unknown family).
void listTypes(std::ostream& out, const std::string& family, const SourceLocation& where = {});

} // namespace sph
