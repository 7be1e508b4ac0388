#include "io/AtomicFile.hpp"

#include "core/InputError.hpp"

#include <unistd.h>

#include <cstdio>
#include <fstream>

namespace sph
{

void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path&)>& write)
{
    std::error_code ec;
    if (!target.parent_path().empty())
    {
        std::filesystem::create_directories(target.parent_path(), ec);
    }
    const std::filesystem::path temporary =
        target.parent_path() /
        ("." + target.filename().string() + ".tmp" + std::to_string(::getpid()));
    try
    {
        write(temporary);
    }
    catch (...)
    {
        std::filesystem::remove(temporary, ec);
        throw;
    }
    std::filesystem::rename(temporary, target, ec);
    if (ec)
    {
        std::filesystem::remove(temporary, ec);
        throw InputError("cannot write '" + target.string() + "': " + ec.message(),
                         {"Check that the folder is writable and the disk is not full."});
    }
}

void writeTextAtomically(const std::filesystem::path& target, const std::string& text)
{
    writeAtomically(target, [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        out.flush();
        if (!out)
        {
            throw InputError("cannot write '" + temporary.string() + "'",
                             {"Check that the folder is writable and the disk is not full."});
        }
    });
}

} // namespace sph
