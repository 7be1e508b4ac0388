#pragma once
// Loads model libraries at run time: first the family libraries named in <prefix>/etc/defaultLibs,
// then the case's own `libs ("libX.so" ...)` from system/controlDict. A library registers its
// models while it loads (static registration objects), so loading it is all it takes.
//
// Where a name is looked for, in order:
//   - a name with a '/' is a path, relative to the case folder;
//   - the sphSolid library folder (where libsphCore.so is);
//   - each folder of the environment variable SPH_LIBRARY_PATH (':'-separated);
//   - the system's search (LD_LIBRARY_PATH, the ld.so cache).
// A failed load is an InputError with dlerror() and a checklist.

#include "SourceLocation.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sph
{

class LibraryLoader
{
public:
    // Loads one library; `where` is the libs entry that named it (for the error message).
    static void load(const std::string& name, const SourceLocation& where,
                     const std::filesystem::path& caseDir);
    // Loads every library listed in <prefix>/etc/defaultLibs.
    static void loadDefaultLibraries();
    // The folder of libsphCore.so.
    static std::filesystem::path libraryDirectory();
    // <prefix>/etc (the folder next to the library folder).
    static std::filesystem::path etcDirectory();
    // Full paths of everything loaded so far, in order.
    static const std::vector<std::string>& loaded();
};

} // namespace sph
