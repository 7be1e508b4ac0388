#pragma once
// What a model sees of a distributed run (issue 14; docs/parallel.md): which local particles
// the rank owns, their global indices, and the operations over the ranks that make a model's
// result the serial one. A rank holds its owned particles and ghosts (copies of other ranks'
// particles), in increasing global index. A model visits the particles that count() (the owned
// ones, so each particle once), combines what it found with the reductions below, finds a
// particle by its global index, and takes from the owners what only they can compute. Serially
// (a default-constructed object) every particle counts, a particle's global index is its index,
// and every operation leaves its argument as it is: one code path for both.
//
// Used by the function objects (every rank holds the same result; only the writer, rank 0,
// writes postProcessing/) and by contact (the bodies' boxes, the ghosts' current volumes).

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

namespace sph
{

struct ParticleRanks
{
    const std::vector<std::uint8_t>* owned = nullptr; // per local particle; null: all owned
    const std::vector<int>* globalId = nullptr;       // per local particle; null: the index
    bool writer = true;                                // this rank writes postProcessing/
    // In place, element by element over the ranks (exact in any order).
    std::function<void(std::vector<double>&)> minimumOverRanks;
    std::function<void(std::vector<double>&)> maximumOverRanks;
    // In place, element by element: the ranks' values added in rank order (the same bits on
    // every rank; the serial sum's to round-off).
    std::function<void(std::vector<double>&)> sumOverRanks;
    // Every rank's `values` joined in rank order, on the writer (elsewhere: empty); the ranks
    // may give different counts.
    std::function<std::vector<double>(const std::vector<double>&)> gatherOnWriter;
    // One value per local particle: each ghost's becomes its owner's.
    std::function<void(std::vector<double>&)> ownersToGhosts;

    bool distributed() const { return owned != nullptr; }
    bool counts(std::size_t a) const { return !owned || (*owned)[a] != 0; }
    std::size_t global(std::size_t a) const
    {
        return globalId ? static_cast<std::size_t>((*globalId)[a]) : a;
    }
    // The local index of the particle of global index g if this rank owns it.
    std::optional<std::size_t> localOwned(std::size_t g) const
    {
        if (!globalId)
        {
            return g;
        }
        const auto at = std::lower_bound(globalId->begin(), globalId->end(), static_cast<int>(g));
        if (at == globalId->end() || *at != static_cast<int>(g))
        {
            return std::nullopt;
        }
        const auto a = static_cast<std::size_t>(at - globalId->begin());
        return counts(a) ? std::optional<std::size_t>(a) : std::nullopt;
    }
    void minimum(std::vector<double>& values) const { apply(minimumOverRanks, values); }
    void maximum(std::vector<double>& values) const { apply(maximumOverRanks, values); }
    void sum(std::vector<double>& values) const { apply(sumOverRanks, values); }
    void shareWithGhosts(std::vector<double>& values) const { apply(ownersToGhosts, values); }
    std::vector<double> onWriter(const std::vector<double>& values) const
    {
        return gatherOnWriter ? gatherOnWriter(values) : values;
    }
    // The values of the particles of global indices `particles`, `width` per particle, on
    // every rank: their owners fill them (fill(a, out) writes `width` values at out for the
    // local particle a), bit for bit (a maximum over -inf elsewhere).
    template <class Fill>
    std::vector<double> fromOwners(const std::vector<std::size_t>& particles, std::size_t width,
                                   Fill&& fill) const
    {
        std::vector<double> values(particles.size() * width,
                                   -std::numeric_limits<double>::infinity());
        for (std::size_t i = 0; i < particles.size(); ++i)
        {
            if (const auto a = localOwned(particles[i]))
            {
                fill(*a, &values[i * width]);
            }
        }
        maximum(values);
        return values;
    }

private:
    static void apply(const std::function<void(std::vector<double>&)>& operation,
                      std::vector<double>& values)
    {
        if (operation)
        {
            operation(values);
        }
    }
};

} // namespace sph
