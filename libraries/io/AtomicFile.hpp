#pragma once
// Atomic file output: the content is written to a temporary file in the same folder
// (".<name>.tmp<pid>"), every write checked, flushed to the disk (fsync) and closed, and only
// then renamed over the target. A reader (ParaView, a restart) never sees half a file, and
// neither a killed run nor a full disk ever replaces a good file with a damaged one.
// Every failure is an IoError naming the target (not the temporary) and the system's reason.

#include <filesystem>
#include <functional>
#include <string>

namespace sph
{

// Calls write(temporaryPath), then syncs the temporary to the disk and renames it over
// `target`. If write throws, or the sync or the rename fails, the temporary is removed and the
// target left untouched. `write` reports its own failures by throwing (IoError for the target).
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path&)>& write);

// Writes `text` to `target` atomically.
void writeTextAtomically(const std::filesystem::path& target, const std::string& text);

// Removes the temporaries that a killed run left in `folder` and its subfolders: only files
// named like ours (".<name>.tmp<pid>") whose process is gone. Nothing if `folder` is missing.
void removeStaleTemporaries(const std::filesystem::path& folder);

} // namespace sph
