#pragma once
// The one exception type for bad input (dictionaries, command line, particle files, libraries).
// Its what() is the complete user-facing message in the style of design guide §4:
//
//   --> sphSolid FATAL INPUT ERROR
//   system/sphSchemes:14:26: unknown stabilisation type 'vidall'
//       stabilisation { type vidall; }
//                            ^~~~~~
//   Valid stabilisation types (4): gradF, hourglass, none, vidal
//   Did you mean 'vidal'?
//
// Applications catch it at top level, print what() and exit with code 1.

#include "SourceLocation.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace sph
{

class InputError : public std::runtime_error
{
public:
    // notes: further lines printed after the quoted source line (valid choices, hints).
    InputError(SourceLocation where, std::string message, std::vector<std::string> notes = {});
    // An error that has no place in an input file (e.g. a missing file).
    explicit InputError(std::string message, std::vector<std::string> notes = {});

    const SourceLocation& where() const { return where_; }
    const std::string& message() const { return message_; }
    const std::vector<std::string>& notes() const { return notes_; }

    // The program name shown in the banner ("sphSolid", "sphParticles", ...).
    static void setProgramName(std::string name);
    static const std::string& programName();

private:
    SourceLocation where_;
    std::string message_;
    std::vector<std::string> notes_;
};

// The formatted message body without the banner: location, message, quoted line, caret, notes.
std::string formatDiagnostic(const SourceLocation& where, const std::string& message,
                             const std::vector<std::string>& notes);

} // namespace sph
