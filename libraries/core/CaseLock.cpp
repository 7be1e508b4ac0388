#include "core/CaseLock.hpp"

#include "core/InputError.hpp"
#include "core/IoError.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <ctime>

namespace sph
{

namespace
{

// The holder as the file says it: "sphSolid, pid 123 on host node1, started 2026-11-26 06:00:00".
std::string holderOf(int fd)
{
    std::string text(512, '\0');
    const ssize_t count = pread(fd, text.data(), text.size(), 0);
    text.resize(count > 0 ? static_cast<std::size_t>(count) : 0);
    while (!text.empty() && (text.back() == '\n' || text.back() == '\0'))
    {
        text.pop_back();
    }
    return text;
}

std::string hostName()
{
    char name[HOST_NAME_MAX + 1] = {};
    return gethostname(name, sizeof name) == 0 ? std::string(name) : std::string("unknown");
}

std::string now()
{
    const std::time_t seconds = std::time(nullptr);
    std::tm local{};
    localtime_r(&seconds, &local);
    char text[64];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S %Z", &local);
    return text;
}

} // namespace

CaseLock::CaseLock(const std::filesystem::path& caseDir, const std::string& program)
{
    const std::filesystem::path file = fileOf(caseDir);
    fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
    {
        throw IoError(file, IoError::reasonFor(errno));
    }
    if (flock(fd_, LOCK_EX | LOCK_NB) != 0)
    {
        const std::string holder = holderOf(fd_);
        ::close(fd_);
        fd_ = -1;
        throw InputError("the case '" + caseDir.string() + "' is in use: " +
                             (holder.empty() ? "another run holds " + file.string() : holder),
                         {"Two runs in one case folder would overwrite each other's output. "
                          "Wait until that run ends, stop it (kill -TERM <pid> writes its last "
                          "level and stops), or copy the case to run it twice.",
                          "-dryRun reads a case in use without running."});
    }
    const std::string previous = holderOf(fd_);
    if (!previous.empty())
    {
        takenOver_ = "taken over the lock of " + previous + ", which no longer runs";
    }
    const std::string holder = program + ", pid " + std::to_string(getpid()) + " on host " +
                               hostName() + ", started " + now() + "\n";
    if (ftruncate(fd_, 0) != 0 ||
        pwrite(fd_, holder.data(), holder.size(), 0) != static_cast<ssize_t>(holder.size()))
    {
        const int error = errno;
        ::close(fd_);
        fd_ = -1;
        throw IoError(file, IoError::reasonFor(error));
    }
}

CaseLock::~CaseLock()
{
    if (fd_ >= 0)
    {
        // Emptied, not removed: a run that opened it meanwhile locks the same file.
        (void)ftruncate(fd_, 0);
        ::close(fd_);
    }
}

long launchedRanks()
{
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "MPI_LOCALNRANKS"})
    {
        if (const char* value = std::getenv(name))
        {
            const long size = std::strtol(value, nullptr, 10);
            if (size > 1)
            {
                return size;
            }
        }
    }
    return 1;
}

} // namespace sph
