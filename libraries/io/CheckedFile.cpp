#include "io/CheckedFile.hpp"

#include "core/IoError.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <utility>

namespace sph
{

namespace
{

// fsync, then close, `fd` (closed in any case); IoError naming `shownAs` if either fails.
void syncAndClose(int fd, const std::filesystem::path& shownAs)
{
    const int synced = ::fsync(fd);
    const int syncError = errno;
    const int closed = ::close(fd);
    if (synced != 0 || closed != 0)
    {
        throw IoError(shownAs, IoError::reasonFor(synced != 0 ? syncError : errno));
    }
}

} // namespace

CheckedFile::CheckedFile(const std::filesystem::path& path, const std::filesystem::path& shownAs,
                         Mode mode)
    : shownAs_(shownAs)
{
    const int flags = O_WRONLY | O_CREAT | O_CLOEXEC | (mode == Mode::append ? O_APPEND : O_TRUNC);
    fd_ = ::open(path.c_str(), flags, 0644);
    if (fd_ < 0)
    {
        throw IoError(shownAs_, IoError::reasonFor(errno));
    }
}

CheckedFile::CheckedFile(CheckedFile&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), shownAs_(std::move(other.shownAs_))
{
}

CheckedFile& CheckedFile::operator=(CheckedFile&& other) noexcept
{
    if (this != &other)
    {
        if (fd_ >= 0)
        {
            ::close(fd_);
        }
        fd_ = std::exchange(other.fd_, -1);
        shownAs_ = std::move(other.shownAs_);
    }
    return *this;
}

CheckedFile::~CheckedFile()
{
    if (fd_ >= 0)
    {
        ::close(fd_);
    }
}

void CheckedFile::write(std::string_view text)
{
    const off_t before = ::lseek(fd_, 0, SEEK_END);
    std::size_t done = 0;
    while (done < text.size())
    {
        const ssize_t written = ::write(fd_, text.data() + done, text.size() - done);
        if (written < 0 && errno == EINTR)
        {
            continue;
        }
        if (written <= 0)
        {
            // write returns 0 only for a zero count; report it as the disk being full
            const int error = written < 0 ? errno : ENOSPC;
            if (before >= 0)
            {
                [[maybe_unused]] const int cut = ::ftruncate(fd_, before);
            }
            throw IoError(shownAs_, IoError::reasonFor(error));
        }
        done += static_cast<std::size_t>(written);
    }
}

void CheckedFile::close()
{
    if (::close(std::exchange(fd_, -1)) != 0)
    {
        throw IoError(shownAs_, IoError::reasonFor(errno));
    }
}

void syncFile(const std::filesystem::path& path, const std::filesystem::path& shownAs)
{
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
    {
        throw IoError(shownAs, IoError::reasonFor(errno));
    }
    syncAndClose(fd, shownAs);
}

} // namespace sph
