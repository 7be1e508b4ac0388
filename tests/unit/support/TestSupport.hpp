#pragma once
// Helpers shared by the unit tests: temporary folders, files, and checks on InputError.

#include "core/Dictionary.hpp"
#include "core/InputError.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

namespace sph::test
{

// A fresh folder under the system temp folder, removed when the object dies.
class TempDir
{
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return path_; }
    // Writes `text` to path()/relative (creating folders) and returns the full path.
    std::filesystem::path write(const std::string& relative, const std::string& text) const;

private:
    std::filesystem::path path_;
};

std::unique_ptr<Dictionary> parse(const std::string& text, const std::string& name = "testDict");

// Runs `action`, requires an InputError at `line`:`column` whose message contains `fragment`;
// returns the full formatted text for further checks.
std::string requireInputError(const std::function<void()>& action, int line, int column,
                              const std::string& fragment);

// The folder of the build tree (set by CTest), for the model libraries and etc/defaultLibs.
std::filesystem::path buildDir();

// Loads the model libraries the way the solver does (once per test process).
void loadModelLibraries();
// Loads one model library by name (e.g. "libsphMaterials.so"), as a case's `libs` would.
void loadLibrary(const std::string& name);

} // namespace sph::test
