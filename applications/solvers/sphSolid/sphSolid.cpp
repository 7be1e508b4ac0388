// sphSolid: the one generic solver. Reads a case, loads the model libraries, builds every
// model by name and runs. See `sphSolid -help` and README.md.
#include "core/Application.hpp"
#include "sphSolid/SolidApplication.hpp"

int main(int argc, char** argv)
{
    return sph::guardedMain([&] { return sph::sphSolidMain(argc, argv); });
}
