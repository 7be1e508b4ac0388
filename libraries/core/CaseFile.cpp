#include "core/CaseFile.hpp"

#include "core/Suggest.hpp"
#include "core/TextFile.hpp"

#include <algorithm>

namespace sph
{

namespace
{

// The name relative to the case folder once '.' and '..' are resolved (symbolic links are
// followed when the file is read, not here); "" when it leaves the folder.
std::filesystem::path insideCase(const std::string& name)
{
    const std::filesystem::path path(name);
    if (name.empty() || path.is_absolute() || path.has_root_name())
    {
        return {};
    }
    const std::filesystem::path normal = path.lexically_normal();
    return normal.empty() || *normal.begin() == ".." ? std::filesystem::path() : normal;
}

// "Files in 'constant': a.dat, b.csv" and "Did you mean ...?" for a name that does not exist.
std::vector<std::string> filesBeside(const std::filesystem::path& file,
                                     const std::filesystem::path& shownFolder)
{
    std::error_code ec;
    std::vector<std::string> names;
    for (std::filesystem::directory_iterator it(file.parent_path(), ec), end;
         !ec && it != end && names.size() < 50; it.increment(ec))
    {
        if (it->is_regular_file(ec))
        {
            names.push_back(it->path().filename().string());
        }
    }
    if (names.empty())
    {
        return {};
    }
    const std::string folder = shownFolder.empty() ? "the case folder" : "'" +
                                                                             shownFolder.string() + "'";
    return {"Files in " + folder + ": " + joinSorted(names),
            didYouMean(file.filename().string(), names)};
}

} // namespace

std::filesystem::path caseFile(const Params& p, std::string_view key,
                               const std::filesystem::path& caseDir, const std::string& what,
                               const std::string& hint)
{
    const std::string& name = p.string(key);
    const std::filesystem::path relative = insideCase(name);
    if (relative.empty())
    {
        p.fail(key, what + " '" + name + "' is outside the case folder",
               {"Name it relative to the case folder, without leaving it (no absolute path, no "
                "'..' above the case), e.g. \"constant/measured.dat\"; copy a file from "
                "elsewhere into the case, so that the case holds what it needs.",
                hint});
    }
    const std::filesystem::path file = caseDir / relative;
    const std::string reason = unreadableReason(file);
    if (!reason.empty())
    {
        std::vector<std::string> notes;
        if (reason == "no such file")
        {
            notes = filesBeside(file, relative.parent_path());
        }
        notes.push_back(hint);
        p.fail(key, "cannot read " + what + " '" + file.string() + "': " + reason,
               std::move(notes));
    }
    return file;
}

} // namespace sph
