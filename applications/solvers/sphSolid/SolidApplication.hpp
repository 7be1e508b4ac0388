#pragma once
// The body of sphSolid, callable from tests: reads a case, loads the model libraries (the
// default ones, then the case's `libs`), builds every model by name and runs (or -dryRun).
// Returns the process exit code; errors propagate as exceptions (see core/Application.hpp).

namespace sph
{

int sphSolidMain(int argc, const char* const* argv);

} // namespace sph
