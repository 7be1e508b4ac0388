#pragma once
// A dictionary's canonical form: what a file records about the input that made it
// (constant/particles.vtu about system/particlesDict), so that a later run can tell whether that
// input has changed since, and which entry changed (the lines themselves are compared: a few
// hundred bytes, so no digest is needed).
//
// One line per entry, `path.to.key value`, in the order written (the order of bodies matters);
// comments, layout, #include and $name are resolved, numbers are written by value (1e2 and 100
// are one), an empty sub-dictionary is `path {}`. Only a change of meaning changes it.

#include "Dictionary.hpp"

#include <string>
#include <vector>

namespace sph
{

struct CanonicalEntry
{
    std::string path;  // "bar.n"
    std::string value; // "40"
    SourceLocation where;

    std::string line() const { return value.empty() ? path : path + " " + value; }
};

std::vector<CanonicalEntry> canonicalEntries(const Dictionary& dict);
std::vector<std::string> canonicalLines(const Dictionary& dict);

} // namespace sph
