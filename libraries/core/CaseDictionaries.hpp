#pragma once
// The dictionary files of a case, parsed once, with the command line's -set overrides applied.
//
//   controlDict   -> system/controlDict       sphSchemes -> system/sphSchemes
//   particlesDict -> system/particlesDict     studyDict  -> system/studyDict
//   bodies        -> constant/bodies         walls      -> constant/walls (optional)
//
// -set path.to.key=value: the first component may name one of the files (controlDict.endTime);
// otherwise the file whose top level holds that key is used. Intermediate components must be
// existing sub-dictionaries; the last one is replaced, or added when it is new (the model's
// schema then checks it like any written key). Values are read with the dictionary syntax, and
// errors in them point into the command line. A -set aimed at a file this application does not
// read (or only reads to check against, as sphSolid does system/particlesDict) is an error that
// names the application that reads it.

#include "Dictionary.hpp"

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace sph
{

class CaseDictionaries
{
public:
    explicit CaseDictionaries(std::filesystem::path caseDir);

    // Reads the named files (see the table above); missing required files are InputErrors.
    void read(const std::vector<std::string>& required,
              const std::vector<std::string>& optional = {});
    // checkedOnly: files read but not used as input (sphSolid reads system/particlesDict only to
    // check constant/particles.vtu against it), so not a -set's target.
    void applySets(const std::vector<std::string>& sets,
                   const std::vector<std::string>& checkedOnly = {});

    bool has(const std::string& name) const { return files_.count(name) > 0; }
    const Dictionary& get(const std::string& name) const;
    const std::filesystem::path& caseDir() const { return caseDir_; }
    // The case folder's name (used for output file names).
    std::string caseName() const;

    // The relative path of a known dictionary ("system/controlDict").
    static std::string relativePath(const std::string& name);
    // The applications that read a known dictionary as their input ("sphParticles").
    static const std::vector<std::string>& readBy(const std::string& name);

private:
    std::filesystem::path caseDir_;
    std::map<std::string, std::unique_ptr<Dictionary>> files_;
    std::vector<std::string> order_;
};

} // namespace sph
