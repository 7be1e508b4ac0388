#include "Suggest.hpp"

#include <algorithm>
#include <cctype>

namespace sph
{

std::size_t editDistance(std::string_view a, std::string_view b)
{
    const auto lower = [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); };
    const std::size_t n = a.size();
    const std::size_t m = b.size();
    std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
    for (std::size_t i = 0; i <= n; ++i)
    {
        d[i][0] = i;
    }
    for (std::size_t j = 0; j <= m; ++j)
    {
        d[0][j] = j;
    }
    for (std::size_t i = 1; i <= n; ++i)
    {
        for (std::size_t j = 1; j <= m; ++j)
        {
            const std::size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) &&
                lower(a[i - 2]) == lower(b[j - 1]))
            {
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
            }
        }
    }
    return d[n][m];
}

std::optional<std::string> closestMatch(std::string_view word,
                                        const std::vector<std::string>& candidates)
{
    std::optional<std::string> best;
    std::size_t bestDistance = 0;
    for (const std::string& candidate : candidates)
    {
        const std::size_t distance = editDistance(word, candidate);
        if (!best || distance < bestDistance || (distance == bestDistance && candidate < *best))
        {
            best = candidate;
            bestDistance = distance;
        }
    }
    // A typo changes a few characters; allow about a third of the word, at least two.
    const std::size_t allowed = std::max<std::size_t>(2, word.size() / 3);
    if (!best || bestDistance > allowed || bestDistance >= std::max(word.size(), best->size()))
    {
        return std::nullopt;
    }
    return best;
}

std::string didYouMean(std::string_view word, const std::vector<std::string>& candidates)
{
    const auto match = closestMatch(word, candidates);
    return match ? "Did you mean '" + *match + "'?" : std::string();
}

std::string joinSorted(std::vector<std::string> words, std::string_view separator)
{
    std::sort(words.begin(), words.end());
    std::string text;
    for (std::size_t i = 0; i < words.size(); ++i)
    {
        if (i > 0)
        {
            text += separator;
        }
        text += words[i];
    }
    return text;
}

} // namespace sph
