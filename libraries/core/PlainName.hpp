#pragma once
// Names from a case that become folder or file names (a function object's
// postProcessing/<name>/, a study's runs/<variant>/, ...): only plain names, so that none can
// leave the case folder (no '/', no "..", not absolute) or end a quoted string in a generated
// script. One check for every such name.

#include "core/Dictionary.hpp"

#include <string>

namespace sph
{

// Letters, digits and _ . + -, at most 64, starting with a letter, a digit or _.
bool isPlainName(const std::string& name);

// Throws an InputError at the entry's key unless its key is a plain name. `what` names the
// entry ("function object", "axis", ...), `usedAs` what the name becomes ("folder and file
// names").
void requirePlainName(const Entry& entry, const std::string& what, const std::string& usedAs);

} // namespace sph
