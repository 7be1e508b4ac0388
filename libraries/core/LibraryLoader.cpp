#include "LibraryLoader.hpp"

#include "DictionaryParser.hpp"
#include "InputError.hpp"
#include "Registry.hpp"
#include "TextFile.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace sph
{

namespace
{

std::vector<std::string>& loadedStorage()
{
    static std::vector<std::string> libraries;
    return libraries;
}

std::vector<std::filesystem::path> candidates(const std::string& name,
                                              const std::filesystem::path& caseDir)
{
    std::vector<std::filesystem::path> result;
    if (name.find('/') != std::string::npos)
    {
        const std::filesystem::path path(name);
        result.push_back(path.is_absolute() ? path : (caseDir / path).lexically_normal());
        return result;
    }
    result.push_back(LibraryLoader::libraryDirectory() / name);
    if (const char* extra = std::getenv("SPH_LIBRARY_PATH"))
    {
        std::stringstream folders(extra);
        std::string folder;
        while (std::getline(folders, folder, ':'))
        {
            if (!folder.empty())
            {
                result.push_back(std::filesystem::path(folder) / name);
            }
        }
    }
    return result;
}

} // namespace

std::filesystem::path LibraryLoader::libraryDirectory()
{
    Dl_info info{};
    if (dladdr(reinterpret_cast<const void*>(&LibraryLoader::libraryDirectory), &info) &&
        info.dli_fname)
    {
        std::error_code ec;
        const auto path = std::filesystem::canonical(info.dli_fname, ec);
        if (!ec)
        {
            return path.parent_path();
        }
    }
    return std::filesystem::current_path();
}

std::filesystem::path LibraryLoader::etcDirectory()
{
    return (libraryDirectory() / ".." / "etc").lexically_normal();
}

const std::vector<std::string>& LibraryLoader::loaded()
{
    return loadedStorage();
}

void LibraryLoader::load(const std::string& name, const SourceLocation& where,
                         const std::filesystem::path& caseDir)
{
    std::string path;
    for (const auto& candidate : candidates(name, caseDir))
    {
        if (std::filesystem::exists(candidate))
        {
            path = candidate.string();
            break;
        }
    }
    const bool searchedOnly = path.empty();
    if (searchedOnly)
    {
        if (name.find('/') != std::string::npos)
        {
            path = candidates(name, caseDir).front().string();
        }
        else
        {
            path = name; // let the system search (LD_LIBRARY_PATH, ld.so cache)
        }
    }
    for (const std::string& done : loadedStorage())
    {
        if (done == path)
        {
            return;
        }
    }
    dlerror();
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    if (!handle)
    {
        const char* reason = dlerror();
        std::vector<std::string> notes{
            "dlerror: " + std::string(reason ? reason : "unknown reason"),
            "Checklist:",
            "  1. Is the name right? Searched: " +
                (name.find('/') != std::string::npos
                     ? path
                     : libraryDirectory().string() +
                           ", $SPH_LIBRARY_PATH, $LD_LIBRARY_PATH and the system folders"),
            "  2. Was the library built? (cmake --build build)",
            "  3. Do its own dependencies resolve? Run: ldd " + path,
            "  4. Was it built against this sphSolid (same compiler and headers)?"};
        throw InputError(where, "cannot load library '" + name + "'", notes);
    }
    loadedStorage().push_back(path);
    const std::vector<std::string> conflicts = RegistryStore::instance().takeConflicts();
    if (!conflicts.empty())
    {
        std::vector<std::string> notes(conflicts.begin() + 1, conflicts.end());
        notes.push_back("Each type name may be registered once; rename the model in one of "
                        "the libraries.");
        throw InputError(where, conflicts.front(), notes);
    }
}

void LibraryLoader::loadDefaultLibraries()
{
    const std::filesystem::path file = etcDirectory() / "defaultLibs";
    const std::string text = readTextFile(
        file, "the list of model libraries",
        {"It is installed next to the library folder " + libraryDirectory().string() + ".",
         "Rebuild (cmake --build build) or reinstall sphSolid."});
    auto source = std::make_shared<const SourceText>(file.string(), text);
    int lineNumber = 0;
    std::stringstream lines(text);
    std::string line;
    while (std::getline(lines, line))
    {
        ++lineNumber;
        const auto hash = line.find('#');
        std::string name = line.substr(0, hash);
        name.erase(0, name.find_first_not_of(" \t"));
        name.erase(name.find_last_not_of(" \t\r") + 1);
        if (!name.empty())
        {
            load(name, SourceLocation{source, lineNumber, 1, static_cast<int>(name.size())},
                 libraryDirectory());
        }
    }
}

} // namespace sph
