#pragma once
// The body of sphParticles, callable from tests: builds constant/particles.vtu from
// system/particlesDict with the generator family. Returns the process exit code; errors
// propagate as exceptions (see core/Application.hpp).

namespace sph
{

int sphParticlesMain(int argc, const char* const* argv);

} // namespace sph
