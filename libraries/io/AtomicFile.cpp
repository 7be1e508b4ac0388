#include "io/AtomicFile.hpp"

#include "core/IoError.hpp"
#include "io/CheckedFile.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <regex>

namespace sph
{

namespace
{

const std::string temporaryMarker = ".tmp";

std::filesystem::path temporaryFor(const std::filesystem::path& target)
{
    return target.parent_path() /
           ("." + target.filename().string() + temporaryMarker + std::to_string(::getpid()));
}

// The process id in a temporary's name ".<name>.tmp<pid>", or 0 if the name is not one of ours.
pid_t writerOf(const std::string& fileName)
{
    static const std::regex pattern(R"(\..+\.tmp([0-9]{1,9}))");
    std::smatch match;
    if (!std::regex_match(fileName, match, pattern))
    {
        return 0;
    }
    return static_cast<pid_t>(std::stol(match[1].str()));
}

// A temporary of a process that still runs is being written (two runs sharing an output
// folder, e.g. sphStudy's), so only those of processes that are gone are removed.
bool processIsGone(pid_t pid)
{
    return pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH;
}

} // namespace

void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path&)>& write)
{
    std::error_code ec;
    if (!target.parent_path().empty())
    {
        std::filesystem::create_directories(target.parent_path(), ec);
    }
    const std::filesystem::path temporary = temporaryFor(target);
    try
    {
        write(temporary);
        // The rename must not reach the disk before the content does, or a crash right after
        // it leaves an empty target.
        syncFile(temporary, target);
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
        throw IoError(target, ec.message());
    }
}

void writeTextAtomically(const std::filesystem::path& target, const std::string& text)
{
    writeAtomically(target, [&](const std::filesystem::path& temporary) {
        CheckedFile file(temporary, target, CheckedFile::Mode::truncate);
        file.write(text);
        file.close();
    });
}

void removeStaleTemporaries(const std::filesystem::path& folder)
{
    std::error_code ec;
    if (!std::filesystem::is_directory(folder, ec))
    {
        return;
    }
    for (auto entry = std::filesystem::recursive_directory_iterator(folder, ec);
         !ec && entry != std::filesystem::recursive_directory_iterator(); entry.increment(ec))
    {
        std::error_code ignored; // a file that cannot be removed is simply left
        const pid_t pid = writerOf(entry->path().filename().string());
        if (pid > 0 && entry->is_regular_file(ignored) && processIsGone(pid))
        {
            std::filesystem::remove(entry->path(), ignored);
        }
    }
}

} // namespace sph
