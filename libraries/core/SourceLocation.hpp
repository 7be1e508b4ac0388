#pragma once
// Where a piece of input came from: file, line, column and the extent of the offending text, so
// that every error can print `file:line:col: message` followed by the line and a caret.

#include <memory>
#include <string>
#include <vector>

namespace sph
{

// The text of one input (a dictionary file or a command-line `-set` argument), kept so that an
// error can quote the offending line long after parsing.
class SourceText
{
public:
    // `includedFrom`: for a file read by #include, the "file:line:col" of that directive, then
    // of the directive that included the including file, and so on outwards.
    SourceText(std::string displayName, const std::string& text,
               std::vector<std::string> includedFrom = {});

    const std::string& displayName() const { return displayName_; }
    const std::vector<std::string>& includedFrom() const { return includedFrom_; }
    // 1-based; returns "" for a line outside the text.
    const std::string& line(int number) const;
    int lineCount() const { return static_cast<int>(lines_.size()); }

private:
    std::string displayName_;
    std::vector<std::string> includedFrom_;
    std::vector<std::string> lines_;
};

struct SourceLocation
{
    std::shared_ptr<const SourceText> source; // null: location unknown
    int line = 0;                             // 1-based; 0: the whole file
    int column = 0;                           // 1-based
    int length = 1;                           // characters to underline

    bool known() const { return source != nullptr; }
    std::string fileName() const { return source ? source->displayName() : std::string(); }
    // "file:line:col" (or "file" when there is no line).
    std::string prefix() const;
};

} // namespace sph
