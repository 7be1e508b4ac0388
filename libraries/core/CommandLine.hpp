#pragma once
// The command line shared by every sphSolid application (Boost.Program_options), OpenFOAM
// style with single-dash long options:
//   -case DIR            the case folder (default: .)
//   -set path.to.key=V   override a dictionary entry after parsing (repeatable)
//   -listTypes [family]  every registered model, its description and its keys
//   -dryRun              read and validate everything, build every model, exit 0
//   -help (also -h), -version
// Applications add their own options with options().

#include "SourceLocation.hpp"

#include <boost/program_options.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sph
{

class CommandLine
{
public:
    CommandLine(std::string program, std::string purpose);

    // Application-specific options (add them before parse()).
    boost::program_options::options_description& options() { return extra_; }
    // Enables -listTypes/-dryRun/-set (not every utility reads models).
    void enableModelOptions(bool listTypes, bool dryRun, bool set);

    // Parses argv. Returns false when the program should exit 0 right away (-help, -version).
    // Bad arguments throw InputError pointing into the command line.
    bool parse(int argc, const char* const* argv);

    const std::filesystem::path& caseDir() const { return caseDir_; }
    const std::vector<std::string>& sets() const { return sets_; }
    bool listTypes() const { return listTypes_; }
    const std::string& listFamily() const { return listFamily_; }
    // Where the family name of -listTypes was typed (for error messages).
    const SourceLocation& listFamilyLocation() const { return listFamilyLocation_; }
    bool dryRun() const { return dryRun_; }
    const boost::program_options::variables_map& values() const { return values_; }
    // argv joined with spaces (for logs).
    const std::string& invocation() const { return invocation_; }

    std::string usage() const;

private:
    std::string program_;
    std::string purpose_;
    boost::program_options::options_description extra_;
    boost::program_options::variables_map values_;
    bool withListTypes_ = true;
    bool withDryRun_ = true;
    bool withSet_ = true;
    std::filesystem::path caseDir_ = ".";
    std::vector<std::string> sets_;
    bool listTypes_ = false;
    std::string listFamily_;
    SourceLocation listFamilyLocation_;
    bool dryRun_ = false;
    std::string invocation_;
};

// The value of the integer option -`name` (e.g. -threads), which must lie in [min, max]: a value
// outside is an InputError at its place in the command line, ending with `why`.
boost::program_options::typed_value<long>* integerOption(const std::string& name, long min,
                                                         long max, const std::string& why);

// The most OpenMP threads a run may ask for (-threads, studyDict's threads): far more than any
// node has cores; a larger number is a typo.
constexpr long maxThreads = 1024;

// The version string of the project (CMake's PROJECT_VERSION).
const char* projectVersion();

// The git revision of the source tree this build was made from (`git describe --always
// --dirty` at build time: cmake/GitRevision.cmake), "unknown" for a build outside a checkout.
const char* gitRevision();

// The command line of the application in this process as a shell would take it back: the
// program's name and each argument, quoted where the shell would split or expand it
// (summary.json). Set by CommandLine::parse(); empty before.
const std::string& processCommandLine();

} // namespace sph
