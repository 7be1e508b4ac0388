// Catch2's main inside an MPI session: tests/parallel runs under `mpirun -np N` (N = 1, 2, 3;
// tests/parallel/CMakeLists.txt), every rank runs every test case, and mpirun fails when any
// rank does.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "parallel/Communicator.hpp"

int main(int argc, char** argv)
{
    sph::MpiSession session(argc, argv);
    return Catch::Session().run(argc, argv);
}
