#include "core/IoError.hpp"

#include <cstring>

namespace sph
{

IoError::IoError(const std::filesystem::path& file, const std::string& reason)
    : std::runtime_error(file.string() + ": cannot write: " + reason)
{
}

IoError::IoError(const std::string& message) : std::runtime_error(message)
{
}

std::string IoError::reasonFor(int error)
{
    return error == 0 ? "unknown reason" : std::strerror(error);
}

} // namespace sph
