#pragma once
// Reads the OpenFOAM subset of design guide §3 into a Dictionary:
//   key value;   name { ... }   (lists (nest))   "strings"   // and /* */ comments
//   #include "file"   (relative to the including file; cycles are errors)
//   $name / $a.b      (copy of an earlier entry, searched outwards from the current dictionary)
//   $name;            (as a statement: merge the entries of dictionary `name` here; later
//                      explicit entries may override what was merged)
// Syntax errors are InputErrors at the exact line and column.

#include "Dictionary.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace sph
{

class DictionaryParser
{
public:
    // displayName: how messages name the file (e.g. "system/controlDict"); included files are
    // named relative to it.
    static std::unique_ptr<Dictionary> parseFile(const std::filesystem::path& path,
                                                 const std::string& displayName);
    static std::unique_ptr<Dictionary> parseString(const std::string& text,
                                                   const std::string& displayName);
    // Parses the value part of `-set key=value` (a stream of items, no ';'). `source` holds the
    // whole argument; the value starts at 1-based column `firstColumn` of its only line.
    static std::vector<Item> parseValue(const std::shared_ptr<const SourceText>& source,
                                        const std::string& text, int firstColumn);
    // Parses the entries of a `-set key={ ... }` value: `text` is what lies between the braces,
    // starting at 1-based column `firstColumn`.
    static std::unique_ptr<Dictionary> parseDictionaryValue(
        const std::shared_ptr<const SourceText>& source, const std::string& text, int firstColumn,
        const std::string& name);
};

} // namespace sph
