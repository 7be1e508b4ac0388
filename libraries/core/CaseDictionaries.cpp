#include "CaseDictionaries.hpp"

#include "DictionaryParser.hpp"
#include "InputError.hpp"
#include "Suggest.hpp"
#include "TextFile.hpp"

#include <algorithm>

namespace sph
{

namespace
{

struct KnownFile
{
    std::string path;
    std::vector<std::string> readBy; // the applications that take it as input
};

const std::map<std::string, KnownFile>& knownFiles()
{
    static const std::map<std::string, KnownFile> files{
        {"controlDict", {"system/controlDict", {"sphSolid"}}},
        {"sphSchemes", {"system/sphSchemes", {"sphSolid", "sphParticles"}}},
        {"particlesDict", {"system/particlesDict", {"sphParticles"}}},
        {"studyDict", {"system/studyDict", {"sphStudy"}}},
        {"bodies", {"constant/bodies", {"sphSolid"}}},
        {"walls", {"constant/walls", {"sphSolid"}}}};
    return files;
}

std::vector<std::string> split(const std::string& path)
{
    std::vector<std::string> parts;
    std::string current;
    for (char c : path)
    {
        if (c == '.' || c == '/')
        {
            parts.push_back(current);
            current.clear();
        }
        else
        {
            current += c;
        }
    }
    parts.push_back(current);
    return parts;
}

// Whether the whole path names an entry of dict (its intermediate components sub-dictionaries).
bool holdsPath(const Dictionary& dict, const std::vector<std::string>& parts)
{
    const Dictionary* at = &dict;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i)
    {
        const Entry* entry = at->find(parts[i]);
        if (!entry || !entry->isDict())
        {
            return false;
        }
        at = &entry->dict();
    }
    return at->find(parts.back()) != nullptr;
}

} // namespace

CaseDictionaries::CaseDictionaries(std::filesystem::path caseDir) : caseDir_(std::move(caseDir)) {}

std::string CaseDictionaries::relativePath(const std::string& name)
{
    const auto it = knownFiles().find(name);
    if (it == knownFiles().end())
    {
        throw std::logic_error("unknown case dictionary '" + name + "'");
    }
    return it->second.path;
}

const std::vector<std::string>& CaseDictionaries::readBy(const std::string& name)
{
    const auto it = knownFiles().find(name);
    if (it == knownFiles().end())
    {
        throw std::logic_error("unknown case dictionary '" + name + "'");
    }
    return it->second.readBy;
}

std::string CaseDictionaries::caseName() const
{
    std::error_code ec;
    const auto path = std::filesystem::weakly_canonical(std::filesystem::absolute(caseDir_), ec);
    const std::string name = path.filename().string();
    return name.empty() ? "case" : name;
}

void CaseDictionaries::read(const std::vector<std::string>& required,
                            const std::vector<std::string>& optional)
{
    const auto readOne = [&](const std::string& name, bool mustExist)
    {
        const std::string relative = relativePath(name);
        const std::filesystem::path path = caseDir_ / relative;
        const std::string reason = unreadableReason(path);
        if (reason == "no such file")
        {
            if (!mustExist)
            {
                return;
            }
            throw InputError("cannot find " + relative + " in the case folder '" +
                                 caseDir_.string() + "'",
                             {"A case holds system/controlDict, system/sphSchemes, "
                              "system/particlesDict and constant/bodies.",
                              "Point -case at a case folder, or copy a tutorial case to start "
                              "from (tutorials/)."});
        }
        if (!reason.empty())
        {
            throw InputError("cannot read " + relative + " in the case folder '" +
                                 caseDir_.string() + "': " + reason,
                             {"It must be a readable text file (a symbolic link to one is fine)."});
        }
        auto dict = DictionaryParser::parseFile(path, relative);
        // An OpenFOAM header `FoamFile { version 2.0; format ascii; class dictionary; ... }` is
        // accepted and ignored, so that files written with OpenFOAM habits and tools load.
        auto& entries = dict->entries();
        entries.erase(std::remove_if(entries.begin(), entries.end(),
                                     [](const Entry& entry)
                                     { return entry.key() == "FoamFile" && entry.isDict(); }),
                      entries.end());
        files_[name] = std::move(dict);
        order_.push_back(name);
    };
    for (const auto& name : required)
    {
        readOne(name, true);
    }
    for (const auto& name : optional)
    {
        readOne(name, false);
    }
}

const Dictionary& CaseDictionaries::get(const std::string& name) const
{
    const auto it = files_.find(name);
    if (it == files_.end())
    {
        throw std::logic_error("case dictionary '" + name + "' was not read");
    }
    return *it->second;
}

void CaseDictionaries::applySets(const std::vector<std::string>& sets,
                                 const std::vector<std::string>& checkedOnly)
{
    // The files a -set may change: those this application reads as its input.
    const auto settable = [&](const std::string& name)
    {
        return files_.count(name) &&
               std::find(checkedOnly.begin(), checkedOnly.end(), name) == checkedOnly.end();
    };
    // Whether this application takes a known file as input (when the case has it).
    const auto readHere = [&](const std::string& name)
    {
        const auto& readers = readBy(name);
        return std::find(readers.begin(), readers.end(), InputError::programName()) !=
                   readers.end() &&
               std::find(checkedOnly.begin(), checkedOnly.end(), name) == checkedOnly.end();
    };
    std::vector<std::string> targets;
    std::copy_if(order_.begin(), order_.end(), std::back_inserter(targets), settable);

    for (const std::string& argument : sets)
    {
        const std::string line = "-set " + argument;
        auto source = std::make_shared<const SourceText>("command line", line);
        const auto at = [&](std::size_t offset, std::size_t length)
        {
            return SourceLocation{source, 1, static_cast<int>(5 + offset + 1),
                                  static_cast<int>(std::max<std::size_t>(1, length))};
        };
        const std::size_t equals = argument.find('=');
        if (equals == std::string::npos || equals == 0)
        {
            throw InputError(at(0, argument.size()), "-set needs the form path.to.key=value",
                             {"Example: -set endTime=1e-3 or -set stabilisation.type=gradF"});
        }
        const std::string path = argument.substr(0, equals);
        const std::string valueText = argument.substr(equals + 1);
        std::vector<std::string> parts = split(path);
        for (const auto& part : parts)
        {
            if (part.empty())
            {
                throw InputError(at(0, path.size()), "empty key name in -set path '" + path + "'");
            }
        }
        // A value in braces replaces a whole sub-dictionary: -set 'material={ type X; ... }'.
        const std::size_t open = valueText.find_first_not_of(" \t");
        const std::size_t close = valueText.find_last_not_of(" \t");
        const bool isDictValue = open != std::string::npos && valueText[open] == '{';
        if (isDictValue && valueText[close] != '}')
        {
            throw InputError(
                at(equals + 1 + open, 1), "-set: the '{' of this value is not closed",
                {"Write -set 'path.to.dict={ key value; ... }' (quote it for the shell)."});
        }
        std::vector<Item> items;
        std::unique_ptr<Dictionary> dictValue;
        if (isDictValue)
        {
            dictValue = DictionaryParser::parseDictionaryValue(
                source, valueText.substr(open + 1, close - open - 1),
                static_cast<int>(5 + equals + 2 + open + 1), parts.back());
        }
        else
        {
            items =
                DictionaryParser::parseValue(source, valueText, static_cast<int>(5 + equals + 2));
        }

        // A -set for a file another application reads would change nothing here (a -set of
        // system/particlesDict given to sphSolid left the particles as they were).
        const auto notReadHere = [&](const std::string& name, SourceLocation where)
        {
            const std::string& program = InputError::programName();
            const std::vector<std::string>& readers = readBy(name);
            std::string names;
            for (std::size_t i = 0; i < readers.size(); ++i)
            {
                names += (i ? " and " : "") + readers[i];
            }
            std::vector<std::string> notes;
            if (files_.count(name))
            {
                // Only a checked-only file is read and yet not a target.
                notes.push_back(program + " reads " + relativePath(name) +
                                " only to check that constant/particles.vtu was made from it.");
            }
            notes.push_back("Give the -set to " + readers.front() + ": " + readers.front() +
                            " -set " + argument +
                            (name == "particlesDict" ? " (then run " + program + ")" : ""));
            return InputError(where,
                              "-set: " + relativePath(name) + " is read by " + names + ", not by " +
                                  program,
                              notes);
        };

        // Which file?
        std::string file;
        std::vector<std::string> holders;
        for (const auto& name : targets)
        {
            if (files_.at(name)->find(parts.front()))
            {
                holders.push_back(name);
            }
        }
        if (settable(parts.front()) && parts.size() > 1)
        {
            file = parts.front();
            parts.erase(parts.begin());
        }
        else if (parts.size() > 1 && holders.empty() && knownFiles().count(parts.front()) &&
                 !readHere(parts.front()))
        {
            throw notReadHere(parts.front(), at(0, parts.front().size()));
        }
        else
        {
            // A path written whole in one file wins over a file that only has its first key
            // (`bar.n` is a key of particlesDict's bar, not of the bar of constant/bodies).
            std::vector<std::string> whole;
            std::copy_if(holders.begin(), holders.end(), std::back_inserter(whole),
                         [&](const std::string& name)
                         { return holdsPath(*files_.at(name), parts); });
            for (const auto& name : checkedOnly)
            {
                if (files_.count(name) && holdsPath(*files_.at(name), parts) && whole.empty())
                {
                    throw notReadHere(name, at(0, path.size()));
                }
            }
            if (holders.size() > 1)
            {
                const auto& choices = whole.empty() ? holders : whole;
                std::string prefixed;
                for (std::size_t i = 0; i < choices.size(); ++i)
                {
                    prefixed += (i ? " or -set " : "-set ") + choices[i] + "." + argument;
                }
                throw InputError(at(0, parts.front().size()),
                                 "-set key '" + parts.front() + "' is ambiguous: it is in " +
                                     joinSorted(holders),
                                 {"Prefix the file: " + prefixed});
            }
            if (holders.empty())
            {
                std::vector<std::string> topKeys;
                for (const auto& name : targets)
                {
                    for (const auto& key : files_.at(name)->keys())
                    {
                        topKeys.push_back(key);
                    }
                }
                std::vector<std::string> notes{"To add a new top-level key, prefix its file (" +
                                               joinSorted(targets) + "): -set " +
                                               (targets.empty() ? "controlDict" : targets.front()) +
                                               "." + argument};
                const std::string hint = didYouMean(parts.front(), topKeys);
                if (!hint.empty())
                {
                    notes.insert(notes.begin(), hint);
                }
                throw InputError(
                    at(0, parts.front().size()),
                    "-set: no case dictionary has a top-level key '" + parts.front() + "'", notes);
            }
            file = holders.front();
        }

        Dictionary* dict = files_.at(file).get();
        std::size_t offset = path.size() - [&]
        {
            std::size_t length = 0;
            for (std::size_t i = 0; i < parts.size(); ++i)
            {
                length += parts[i].size() + (i ? 1 : 0);
            }
            return length;
        }();
        for (std::size_t i = 0; i + 1 < parts.size(); ++i)
        {
            Entry* entry = dict->find(parts[i]);
            if (!entry || !entry->isDict())
            {
                std::vector<std::string> notes;
                const std::string hint = didYouMean(parts[i], dict->keys());
                if (!hint.empty())
                {
                    notes.push_back(hint);
                }
                notes.push_back("'" + dict->displayName() + "' has: " + joinSorted(dict->keys()));
                throw InputError(at(offset, parts[i].size()),
                                 entry ? "-set: '" + parts[i] + "' is not a dictionary"
                                       : "-set: '" + dict->displayName() +
                                             "' has no sub-dictionary '" + parts[i] + "'",
                                 notes);
            }
            offset += parts[i].size() + 1;
            dict = &entry->dict();
        }
        const std::string& key = parts.back();
        Entry* entry = dict->find(key);
        if (dictValue)
        {
            Entry replacement(key, at(offset, key.size()), std::move(dictValue));
            if (entry)
            {
                *entry = std::move(replacement);
            }
            else
            {
                dict->add(std::move(replacement));
            }
        }
        else if (entry)
        {
            if (entry->isDict())
            {
                throw InputError(
                    at(offset, key.size()),
                    "-set: '" + key + "' is a dictionary; set one of its keys",
                    {"For example -set " + path + "." +
                         (entry->dict().empty() ? "type" : entry->dict().keys().front()) + "=...",
                     "or replace it whole: -set '" + path + "={ ... }'"});
            }
            entry->setItems(std::move(items));
        }
        else
        {
            dict->add(Entry(key, at(offset, key.size()), std::move(items)));
        }
    }
}

} // namespace sph
