#pragma once
// A per-particle quantity of variable length: particle a holds entries(a) entries of width()
// numbers each (gradF's stress samples: one per neighbour pair, each with its plastic state).
// Registered in the field registry (ParticleFields::bindRagged), it moves with its particle
// between ranks (parallel/ParticleExchange) and is restart data (solver/StateFile: the entries
// of the written particles, in their order, as the field data "restart:<name>", and each
// particle's entry count as the point array "restart:<name>Count").
//
// The owner keeps its own storage (laid out as its loops want it); this interface only copies
// a particle's entries out and replaces the whole set.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace sph
{

class RaggedArray
{
public:
    virtual ~RaggedArray() = default;

    virtual const std::string& name() const = 0;
    // Numbers per entry (the same for every particle).
    virtual std::size_t width() const = 0;
    // The particle count and particle a's entries.
    virtual std::size_t size() const = 0;
    virtual std::size_t entries(std::size_t a) const = 0;
    // Copies particle a's entries (entries(a) * width() numbers) to out.
    virtual void get(std::size_t a, double* out) const = 0;
    // Replaces every particle: particle a gets counts[a] entries, the values of all of them
    // one particle after another.
    virtual void assign(const std::vector<std::size_t>& counts, std::vector<double> values) = 0;

    // Keeps the particles with keep[a] != 0, in order (the rest dropped), then adds `added`
    // particles without entries.
    void keepOnly(const std::vector<std::uint8_t>& keep, std::size_t added = 0)
    {
        std::vector<std::size_t> counts;
        std::vector<double> values;
        for (std::size_t a = 0; a < keep.size(); ++a)
        {
            if (keep[a])
            {
                counts.push_back(entries(a));
                values.resize(values.size() + counts.back() * width());
                get(a, values.data() + values.size() - counts.back() * width());
            }
        }
        counts.resize(counts.size() + added, 0);
        assign(counts, std::move(values));
    }
    // n particles: the first n kept, any added without entries.
    void resize(std::size_t n)
    {
        if (n != size())
        {
            std::vector<std::uint8_t> keep(size(), 0);
            std::fill(keep.begin(), keep.begin() + static_cast<long>(std::min(n, size())), 1);
            keepOnly(keep, n > size() ? n - size() : 0);
        }
    }
};

// The plainest ragged field: each particle's entries in a vector of their own (for few or
// small entries; gradF's samples keep a layout along the neighbour list instead).
class RaggedVectors final : public RaggedArray
{
public:
    RaggedVectors(std::string name, std::size_t width) : name_(std::move(name)), width_(width) {}

    // values[a]: particle a's entries, width() numbers each.
    std::vector<std::vector<double>> values;

    const std::string& name() const override { return name_; }
    std::size_t width() const override { return width_; }
    std::size_t size() const override { return values.size(); }
    std::size_t entries(std::size_t a) const override { return values[a].size() / width_; }
    void get(std::size_t a, double* out) const override
    {
        std::copy(values[a].begin(), values[a].end(), out);
    }
    void assign(const std::vector<std::size_t>& counts, std::vector<double> all) override
    {
        std::size_t total = 0;
        for (const std::size_t count : counts)
        {
            total += count * width_;
        }
        if (total != all.size())
        {
            throw std::logic_error("ragged field '" + name_ + "': " + std::to_string(all.size()) +
                                   " numbers for " + std::to_string(total));
        }
        values.assign(counts.size(), {});
        auto from = all.begin();
        for (std::size_t a = 0; a < counts.size(); ++a)
        {
            const auto end = from + static_cast<long>(counts[a] * width_);
            values[a].assign(from, end);
            from = end;
        }
    }

private:
    std::string name_;
    std::size_t width_;
};

} // namespace sph
