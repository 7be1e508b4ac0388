// libFuzzer target for the dictionary parser (issue 12, item 10): the bytes are a case
// dictionary, parsed through the entry the solver uses (DictionaryParser::parseFile, file on
// disk, byte-order mark and #include handling included). An InputError is a correct answer to
// bad input; a crash, a sanitizer report, a hang, a leak or any other exception is a finding.
#include "core/DictionaryParser.hpp"
#include "core/InputError.hpp"

#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace
{

// A private folder for the dictionary and the files it may #include. Two of them exist so that
// nested and cyclic includes are reached: "inner" (a few entries) and "self" (includes itself).
const std::filesystem::path& workFolder()
{
    static const std::filesystem::path folder = [] {
        std::filesystem::path made = std::filesystem::temp_directory_path() /
                                     ("sphDictionaryFuzzer." + std::to_string(::getpid()));
        std::filesystem::create_directories(made);
        std::ofstream(made / "inner") << "a 1;\nb { c (1 2 3); d \"text\"; }\n";
        std::ofstream(made / "self") << "e 2;\n#include \"self\"\n";
        std::atexit([] {
            std::error_code ec;
            std::filesystem::remove_all(workFolder(), ec);
        });
        return made;
    }();
    return folder;
}

// The lexer knows no escapes that make a '/', so an #include without one names a file of the
// work folder (or the folder itself): the fuzzer never reads the rest of the filesystem.
bool readsOutsideWorkFolder(std::string_view text)
{
    return text.find("#include") != std::string_view::npos &&
           text.find('/') != std::string_view::npos;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string text(reinterpret_cast<const char*>(data), size);
    if (readsOutsideWorkFolder(text))
    {
        return -1; // not added to the corpus
    }
    const std::filesystem::path file = workFolder() / "controlDict";
    std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
    try
    {
        const auto dictionary = sph::DictionaryParser::parseFile(file, "system/controlDict");
    }
    catch (const sph::InputError& error)
    {
        // The message is formatted when the error is made; reading it checks it is complete.
        [[maybe_unused]] const std::size_t length = std::string_view(error.what()).size();
    }
    return 0;
}
