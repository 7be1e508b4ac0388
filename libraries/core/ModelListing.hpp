#pragma once
// -listTypes of every application: every registered model of every family (or of one family)
// with its description, library, dimensions, keys and per-particle fields, from the registry
// (so the models of a case's own libraries appear once they are loaded).

#include "SourceLocation.hpp"

#include <iosfwd>
#include <string>

namespace sph
{

// `where`: where the family name was typed (for the error on an unknown family).
void listTypes(std::ostream& out, const std::string& family, const SourceLocation& where = {});

} // namespace sph
