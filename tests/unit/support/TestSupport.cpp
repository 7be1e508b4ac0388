#include "support/TestSupport.hpp"

#include "core/DictionaryParser.hpp"
#include "core/LibraryLoader.hpp"

#include <atomic>
#include <cstdlib>
#include <fstream>
#include <random>

namespace sph::test
{

TempDir::TempDir()
{
    static std::atomic<int> counter{0};
    std::random_device seed;
    path_ = std::filesystem::temp_directory_path() /
            ("sphTest_" + std::to_string(seed()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
}

TempDir::~TempDir()
{
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
}

std::filesystem::path TempDir::write(const std::string& relative, const std::string& text) const
{
    const auto file = path_ / relative;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << text;
    return file;
}

std::unique_ptr<Dictionary> parse(const std::string& text, const std::string& name)
{
    return DictionaryParser::parseString(text, name);
}

std::string requireInputError(const std::function<void()>& action, int line, int column,
                              const std::string& fragment)
{
    try
    {
        action();
    }
    catch (const InputError& error)
    {
        INFO(error.what());
        CHECK(error.where().line == line);
        CHECK(error.where().column == column);
        CHECK_THAT(error.message(), Catch::Contains(fragment));
        return error.what();
    }
    FAIL("expected an InputError containing '" << fragment << "'");
    return {};
}

std::filesystem::path buildDir()
{
    if (const char* dir = std::getenv("SPH_TEST_BUILD_DIR"))
    {
        return dir;
    }
    return SPH_BUILD_DIR;
}

void loadModelLibraries()
{
    static const bool loaded = [] {
        LibraryLoader::loadDefaultLibraries();
        return true;
    }();
    (void)loaded;
}

void loadLibrary(const std::string& name)
{
    LibraryLoader::load(name, SourceLocation{}, std::filesystem::current_path());
}

} // namespace sph::test
