// sphParticles: builds the initial particles constant/particles.vtu from system/particlesDict.
// See `sphParticles -help`.
#include "core/Application.hpp"
#include "sphParticles/ParticlesApplication.hpp"

int main(int argc, char** argv)
{
    return sph::guardedMain([&] { return sph::sphParticlesMain(argc, argv); });
}
