#include "TextFile.hpp"

#include "InputError.hpp"

#include <cctype>
#include <fstream>
#include <sstream>

namespace sph
{

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
        std::string message = ec.message();
        if (!message.empty())
        {
            message[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(message[0])));
        }
        return message;
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
    std::ifstream in(path, std::ios::binary);
    if (!in)
    {
        throw InputError("cannot read " + what + " '" + path.string() + "'", std::move(notes));
    }
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace sph
