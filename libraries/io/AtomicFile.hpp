#pragma once
// Atomic file output: the content is written to a temporary file in the same folder, flushed,
// and renamed over the target, so a reader (ParaView, a restart) never sees half a file and a
// killed run never destroys what was already there.

#include <filesystem>
#include <functional>
#include <string>

namespace sph
{

// Calls write(temporaryPath), then renames the temporary over `target`. If write throws, the
// temporary is removed and the target left untouched.
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path&)>& write);

// Writes `text` to `target` atomically.
void writeTextAtomically(const std::filesystem::path& target, const std::string& text);

} // namespace sph
