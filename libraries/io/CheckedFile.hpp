#pragma once
// Writing a file with every system call checked: write (a short or failed write), close, and
// (syncFile) fsync. Streams and VTK report a full disk late, partly or not at all; a file descriptor says
// which call failed and why (errno), so every output file goes through here (io/AtomicFile for
// whole files, functionObjects/DatFile for appended tables).

#include <filesystem>
#include <string_view>

namespace sph
{

class CheckedFile
{
public:
    enum class Mode
    {
        truncate, // a new file (the temporary of an atomic write)
        append    // rows added to an existing table
    };

    // Opens `path`; every error names `shownAs`, the file the user knows (the target of an
    // atomic write, not its temporary). IoError if it cannot be opened.
    CheckedFile(const std::filesystem::path& path, const std::filesystem::path& shownAs, Mode mode);
    CheckedFile(CheckedFile&& other) noexcept;
    CheckedFile& operator=(CheckedFile&& other) noexcept;
    CheckedFile(const CheckedFile&) = delete;
    CheckedFile& operator=(const CheckedFile&) = delete;
    ~CheckedFile(); // closes unchecked: only reached so after an error already thrown

    // Writes all of `text` or nothing: after a failure the file is cut back to its length
    // before the call (a table never keeps half a row), then IoError.
    void write(std::string_view text);
    // Closes; IoError if that fails (an NFS server reports a failed write only here). The
    // flush to the disk is writeAtomically's syncFile, once per file.
    void close();

private:
    int fd_ = -1;
    std::filesystem::path shownAs_;
};

// Flushes the written file `path` to the disk (fsync); IoError naming `shownAs` on failure.
void syncFile(const std::filesystem::path& path, const std::filesystem::path& shownAs);

} // namespace sph
