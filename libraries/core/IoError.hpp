#pragma once
// The exception for output that could not be written for a reason outside the case: a full
// disk, a file-size limit, a folder that stopped being writable. It is neither bad input (the
// case is fine, running it again on a disk with room works) nor a bug, so it has its own banner
// and exit code (core/Application.hpp): "--> sphSolid FATAL I/O ERROR", exit 4.
// The message names the file the user knows (VTK/case_3.vtu), never the temporary file it was
// being written through, and the operating system's reason ("No space left on device").

#include <filesystem>
#include <stdexcept>
#include <string>

namespace sph
{

class IoError : public std::runtime_error
{
public:
    // what(): "<file>: cannot write: <reason>"
    IoError(const std::filesystem::path& file, const std::string& reason);

    // what(): `message` as it is, for an I/O error another program reported (sphStudy passes
    // on its solver's).
    explicit IoError(const std::string& message);

    // The reason for the error number `error` (errno), as strerror gives it.
    static std::string reasonFor(int error);
};

} // namespace sph
