// How the particles travel between ranks (parallel/ParticleExchange.hpp): each as a row of
// doubles, its global id, every stored field of the registry, then each ragged field's entry
// count and entries; and how a rank's rows become its local particles again, in increasing
// global id. The exchanges themselves (migrate, ghosts, refreshes) are ParticleExchange.cpp.
#include "parallel/ParticleExchange.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace sph
{

template <int D>
std::size_t ParticleExchange<D>::rowWidth(const ParticleFields<D>& fields)
{
    std::size_t width = 1; // the global id
    for (const auto& field : fields.all())
    {
        if (field.array->stored())
        {
            width += static_cast<std::size_t>(field.components());
        }
    }
    return width;
}

template <int D>
void ParticleExchange<D>::appendRow(const ParticleFields<D>& fields, std::size_t a,
                                    double globalId, Rows& rows)
{
    rows.push_back(globalId);
    double value[D * D * D];
    for (const auto& field : fields.all())
    {
        if (field.array->stored())
        {
            field.array->get(a, value);
            rows.insert(rows.end(), value, value + field.components());
        }
    }
    // Then each ragged field: the particle's entry count, then its entries.
    for (const RaggedArray* array : fields.ragged())
    {
        const std::size_t count = array->entries(a);
        rows.push_back(static_cast<double>(count));
        rows.resize(rows.size() + count * array->width());
        array->get(a, rows.data() + rows.size() - count * array->width());
    }
}

// Where each row of `rows` starts (rows are longer than rowWidth by their ragged entries).
template <int D>
std::vector<std::size_t> ParticleExchange<D>::rowStarts(const ParticleFields<D>& fields,
                                                        const Rows& rows)
{
    const std::size_t width = rowWidth(fields);
    std::vector<std::size_t> starts;
    std::size_t at = 0;
    while (at < rows.size())
    {
        starts.push_back(at);
        at += width;
        for (const RaggedArray* array : fields.ragged())
        {
            if (at >= rows.size())
            {
                throw std::logic_error("ParticleExchange: ranks disagree on the particle fields");
            }
            at += 1 + static_cast<std::size_t>(rows[at]) * array->width();
        }
        if (at > rows.size())
        {
            throw std::logic_error("ParticleExchange: ranks disagree on the particle fields");
        }
    }
    return starts;
}

template <int D>
void ParticleExchange<D>::replaceBy(ParticleFields<D>& fields, const Rows& rows,
                                    std::vector<std::size_t>& origin)
{
    const std::size_t width = rowWidth(fields);
    const std::vector<std::size_t> starts = rowStarts(fields, rows);
    const std::size_t count = starts.size();
    origin.resize(count);
    std::iota(origin.begin(), origin.end(), std::size_t{0});
    std::sort(origin.begin(), origin.end(),
              [&](std::size_t i, std::size_t j) { return rows[starts[i]] < rows[starts[j]]; });
    for (std::size_t k = 1; k < count; ++k)
    {
        if (rows[starts[origin[k]]] == rows[starts[origin[k - 1]]])
        {
            throw std::logic_error("ParticleExchange: particle " +
                                   std::to_string(static_cast<long long>(rows[starts[origin[k]]])) +
                                   " is held twice on one rank");
        }
    }
    // The ragged fields first, at their new size, so that resizing the registry keeps them.
    std::vector<std::size_t> raggedAt(count);
    for (std::size_t k = 0; k < count; ++k)
    {
        raggedAt[k] = starts[origin[k]] + width;
    }
    for (RaggedArray* array : fields.ragged())
    {
        std::vector<std::size_t> entries(count);
        std::size_t total = 0;
        for (std::size_t k = 0; k < count; ++k)
        {
            entries[k] = static_cast<std::size_t>(rows[raggedAt[k]]);
            total += entries[k];
        }
        std::vector<double> values(total * array->width());
        double* out = values.data();
        for (std::size_t k = 0; k < count; ++k)
        {
            const double* in = &rows[raggedAt[k] + 1];
            out = std::copy(in, in + entries[k] * array->width(), out);
            raggedAt[k] += 1 + entries[k] * array->width();
        }
        array->assign(entries, std::move(values));
    }
    fields.resize(count);
    for (std::size_t k = 0; k < count; ++k)
    {
        const double* value = &rows[starts[origin[k]] + 1];
        for (auto& field : fields.all())
        {
            if (field.array->stored())
            {
                field.array->set(k, value);
                value += field.components();
            }
        }
    }
}

// ParticleExchange<D> is instantiated in ParticleExchange.cpp; these are its members defined
// here.
#define SPH_EXCHANGE_ROWS(D)                                                                        \
    template std::size_t ParticleExchange<D>::rowWidth(const ParticleFields<D>&);                  \
    template void ParticleExchange<D>::appendRow(const ParticleFields<D>&, std::size_t, double,    \
                                                 Rows&);                                           \
    template std::vector<std::size_t> ParticleExchange<D>::rowStarts(const ParticleFields<D>&,     \
                                                                      const Rows&);                \
    template void ParticleExchange<D>::replaceBy(ParticleFields<D>&, const Rows&,                  \
                                                 std::vector<std::size_t>&);
SPH_EXCHANGE_ROWS(1)
SPH_EXCHANGE_ROWS(2)
SPH_EXCHANGE_ROWS(3)
#undef SPH_EXCHANGE_ROWS

} // namespace sph
