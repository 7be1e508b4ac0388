#pragma once
// "Did you mean" support: the closest candidate by edit distance, and sorted listings.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sph
{

// Damerau-Levenshtein (optimal string alignment) distance, case-insensitive.
std::size_t editDistance(std::string_view a, std::string_view b);

// The candidate closest to `word`, if it is close enough to be a plausible typo.
std::optional<std::string> closestMatch(std::string_view word,
                                        const std::vector<std::string>& candidates);

// "Did you mean 'x'?" or "" when nothing is close.
std::string didYouMean(std::string_view word, const std::vector<std::string>& candidates);

// Sorted, comma-separated.
std::string joinSorted(std::vector<std::string> words, std::string_view separator = ", ");

} // namespace sph
