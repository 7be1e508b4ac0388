#include "TextFile.hpp"

#include "InputError.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>

namespace sph
{

namespace
{

std::string lowerFirst(std::string message)
{
    if (!message.empty())
    {
        message[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(message[0])));
    }
    return message;
}

} // namespace

std::string unreadableReason(const std::filesystem::path& path)
{
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (status.type() == std::filesystem::file_type::not_found)
    {
        return "no such file";
    }
    if (ec)
    {
        return lowerFirst(ec.message());
    }
    if (std::filesystem::is_directory(status))
    {
        return "it is a folder, not a file";
    }
    if (!std::filesystem::is_regular_file(status))
    {
        return "it is not a regular file";
    }
    std::ifstream in(path, std::ios::binary);
    if (!in)
    {
        return "it cannot be opened (permission denied?)";
    }
    return "";
}

std::string readTextFile(const std::filesystem::path& path, const std::string& what,
                         std::vector<std::string> notes)
{
    // Every file a case names goes through here: a device (/dev/zero, read until memory runs
    // out), a FIFO (blocks for ever) or a folder is refused before it is opened.
    const std::string reason = unreadableReason(path);
    if (!reason.empty())
    {
        throw InputError("cannot read " + what + " '" + path.string() + "': " + reason,
                         std::move(notes));
    }
    // Read with the system's calls, so that a read error is seen: a stream takes it for the
    // end of the file (`#include "/proc/self/mem"` read as empty; issue 31).
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
    {
        throw InputError("cannot read " + what + " '" + path.string() + "': " +
                             lowerFirst(std::strerror(errno)),
                         std::move(notes));
    }
    std::string text;
    char buffer[1 << 16];
    for (;;)
    {
        const ssize_t count = ::read(fd, buffer, sizeof buffer);
        if (count < 0 && errno == EINTR)
        {
            continue;
        }
        if (count < 0)
        {
            const int error = errno;
            ::close(fd);
            throw InputError("cannot read " + what + " '" + path.string() + "': " +
                                 lowerFirst(std::strerror(error)) + " after " +
                                 std::to_string(text.size()) + " bytes",
                             std::move(notes));
        }
        if (count == 0)
        {
            break;
        }
        text.append(buffer, static_cast<std::size_t>(count));
    }
    ::close(fd);
    return text;
}

} // namespace sph
