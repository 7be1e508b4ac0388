#include "parallel/ParticleExchange.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace sph
{

template <int D>
void ParticleExchange<D>::countSent(const std::vector<Rows>& toEach)
{
    bytesSent_ = 0;
    for (std::size_t r = 0; r < toEach.size(); ++r)
    {
        if (static_cast<int>(r) != comm_.rank())
        {
            bytesSent_ += toEach[r].size() * sizeof(double);
        }
    }
    totalBytesSent_ += bytesSent_;
}

template <int D>
void ParticleExchange<D>::migrate(ParticleFields<D>& fields, const std::vector<int>& globalId,
                                  const std::vector<int>& destination)
{
    if (ghostCount_ > 0)
    {
        throw std::logic_error("ParticleExchange::migrate: remove the ghosts first");
    }
    const std::size_t n = fields.size();
    if (globalId.size() != n || destination.size() != n)
    {
        throw std::logic_error("ParticleExchange::migrate: one id and destination per particle");
    }
    std::vector<Rows> toEach(static_cast<std::size_t>(comm_.size()));
    for (std::size_t a = 0; a < n; ++a)
    {
        if (destination[a] < 0 || destination[a] >= comm_.size())
        {
            throw std::logic_error("ParticleExchange::migrate: no rank " +
                                   std::to_string(destination[a]));
        }
        appendRow(fields, a, globalId[a], toEach[static_cast<std::size_t>(destination[a])]);
    }
    countSent(toEach);
    const std::vector<Rows> received = comm_.exchange(toEach);
    toEach.clear();
    Rows rows;
    for (const Rows& from : received)
    {
        rows.insert(rows.end(), from.begin(), from.end());
    }
    std::vector<std::size_t> origin;
    replaceBy(fields, rows, origin);
    owned_.clear();
    sendTo_.clear();
    receiveAt_.clear();
    ownedCount_ = fields.size();
}

template <int D>
void ParticleExchange<D>::addGhosts(ParticleFields<D>& fields, const std::vector<Vec<D>>& x,
                                    const std::vector<int>& globalId, double width)
{
    addGhosts(fields, {GhostReach{&x, width}}, globalId);
}

template <int D>
void ParticleExchange<D>::addGhosts(ParticleFields<D>& fields,
                                    const std::vector<GhostReach>& reaches,
                                    const std::vector<int>& globalId)
{
    removeGhosts(fields);
    const std::size_t n = fields.size();
    for (const GhostReach& reach : reaches)
    {
        if (reach.x->size() != n || globalId.size() != n)
        {
            throw std::logic_error("ParticleExchange::addGhosts: one position and id per particle");
        }
    }
    // Every rank's box around its owned particles in each reach's positions (an empty rank's
    // box is empty: lo > hi), rank after rank, then reach after reach.
    std::vector<double> box;
    for (const GhostReach& reach : reaches)
    {
        const std::size_t first = box.size();
        box.resize(first + 2 * D);
        for (int d = 0; d < D; ++d)
        {
            box[first + d] = std::numeric_limits<double>::infinity();
            box[first + D + d] = -std::numeric_limits<double>::infinity();
        }
        for (const Vec<D>& p : *reach.x)
        {
            for (int d = 0; d < D; ++d)
            {
                box[first + d] = std::min(box[first + d], p[d]);
                box[first + D + d] = std::max(box[first + D + d], p[d]);
            }
        }
    }
    const std::vector<double> boxes = comm_.gather(box);
    const auto ranks = static_cast<std::size_t>(comm_.size());
    const auto me = static_cast<std::size_t>(comm_.rank());
    const auto within = [](const double* lo, const Vec<D>& p, double width) {
        const double* hi = lo + D;
        double distance2 = 0.0;
        for (int d = 0; d < D; ++d)
        {
            const double outside = std::max({0.0, lo[d] - p[d], p[d] - hi[d]});
            distance2 += outside * outside;
        }
        return lo[0] <= hi[0] && distance2 <= width * width;
    };

    sendTo_.assign(ranks, {});
    std::vector<Rows> toEach(ranks);
    for (std::size_t r = 0; r < ranks; ++r)
    {
        if (r == me)
        {
            continue;
        }
        for (std::size_t a = 0; a < n; ++a)
        {
            bool wanted = false;
            for (std::size_t i = 0; i < reaches.size() && !wanted; ++i)
            {
                wanted = within(&boxes[(r * reaches.size() + i) * 2 * D], (*reaches[i].x)[a],
                                reaches[i].width);
            }
            if (wanted)
            {
                sendTo_[r].push_back(a);
                appendRow(fields, a, globalId[a], toEach[r]);
            }
        }
    }
    countSent(toEach);
    const std::vector<Rows> received = comm_.exchange(toEach);
    toEach.clear();

    // This rank's own rows first (row a = owned particle a), then each rank's ghosts in turn.
    Rows rows;
    rows.reserve((n + 1) * rowWidth(fields));
    for (std::size_t a = 0; a < n; ++a)
    {
        appendRow(fields, a, globalId[a], rows);
    }
    std::vector<std::size_t> firstRowOf(ranks + 1, n);
    for (std::size_t r = 0; r < ranks; ++r)
    {
        firstRowOf[r + 1] = firstRowOf[r] + rowStarts(fields, received[r]).size();
        rows.insert(rows.end(), received[r].begin(), received[r].end());
    }
    std::vector<std::size_t> origin;
    replaceBy(fields, rows, origin);

    // Where each row landed: the owned particles' new indices and the ghosts' slots.
    std::vector<std::size_t> localOfRow(origin.size());
    for (std::size_t k = 0; k < origin.size(); ++k)
    {
        localOfRow[origin[k]] = k;
    }
    owned_.assign(origin.size(), 0);
    for (std::size_t a = 0; a < n; ++a)
    {
        owned_[localOfRow[a]] = 1;
    }
    for (auto& list : sendTo_)
    {
        for (std::size_t& a : list)
        {
            a = localOfRow[a];
        }
    }
    receiveAt_.assign(ranks, {});
    for (std::size_t r = 0; r < ranks; ++r)
    {
        for (std::size_t row = firstRowOf[r]; row < firstRowOf[r + 1]; ++row)
        {
            receiveAt_[r].push_back(localOfRow[row]);
        }
    }
    ownedCount_ = n;
    ghostCount_ = origin.size() - n;
}

template <int D>
void ParticleExchange<D>::updateGhosts(ParticleFields<D>& fields,
                                       const std::vector<std::string>& names)
{
    std::vector<FieldArray*> arrays;
    std::vector<int> components;
    for (const std::string& name : names)
    {
        auto found = std::find_if(fields.all().begin(), fields.all().end(),
                                  [&](const auto& field) { return field.spec.name() == name; });
        if (found == fields.all().end() || !found->array->stored())
        {
            throw std::logic_error("ParticleExchange::updateGhosts: no stored field '" + name + "'");
        }
        arrays.push_back(found->array.get());
        components.push_back(found->components());
    }
    const auto ranks = static_cast<std::size_t>(comm_.size());
    std::vector<Rows> toEach(ranks);
    double value[D * D * D];
    for (std::size_t r = 0; r < sendTo_.size(); ++r)
    {
        for (const std::size_t a : sendTo_[r])
        {
            for (std::size_t f = 0; f < arrays.size(); ++f)
            {
                arrays[f]->get(a, value);
                toEach[r].insert(toEach[r].end(), value, value + components[f]);
            }
        }
    }
    countSent(toEach);
    const std::size_t perParticle = std::accumulate(components.begin(), components.end(), std::size_t{0});
    const std::vector<Rows> received = comm_.exchangeKnown(toEach, receiveCounts(perParticle));
    for (std::size_t r = 0; r < receiveAt_.size(); ++r)
    {
        if (received[r].size() != receiveAt_[r].size() * perParticle)
        {
            throw std::logic_error("ParticleExchange::updateGhosts: ranks disagree on the ghosts");
        }
        const double* in = received[r].data();
        for (const std::size_t slot : receiveAt_[r])
        {
            for (std::size_t f = 0; f < arrays.size(); ++f)
            {
                arrays[f]->set(slot, in);
                in += components[f];
            }
        }
    }
}

// How many values each rank sends this one in a refresh of its ghosts, `perGhost` each: the
// ghost pattern is fixed between gatherings, so no counts need exchanging.
template <int D>
std::vector<std::size_t> ParticleExchange<D>::receiveCounts(std::size_t perGhost) const
{
    std::vector<std::size_t> counts(static_cast<std::size_t>(comm_.size()), 0);
    for (std::size_t r = 0; r < receiveAt_.size(); ++r)
    {
        counts[r] = receiveAt_[r].size() * perGhost;
    }
    return counts;
}

template <int D>
void ParticleExchange<D>::updateGhostValues(std::vector<double>& values)
{
    if (values.size() != ownedCount_ + ghostCount_)
    {
        throw std::logic_error("ParticleExchange::updateGhostValues: one value per local particle");
    }
    std::vector<Rows> toEach(static_cast<std::size_t>(comm_.size()));
    for (std::size_t r = 0; r < sendTo_.size(); ++r)
    {
        for (const std::size_t a : sendTo_[r])
        {
            toEach[r].push_back(values[a]);
        }
    }
    countSent(toEach);
    const std::vector<Rows> received = comm_.exchangeKnown(toEach, receiveCounts(1));
    for (std::size_t r = 0; r < receiveAt_.size(); ++r)
    {
        if (received[r].size() != receiveAt_[r].size())
        {
            throw std::logic_error("ParticleExchange::updateGhostValues: ranks disagree on the ghosts");
        }
        for (std::size_t k = 0; k < receiveAt_[r].size(); ++k)
        {
            values[receiveAt_[r][k]] = received[r][k];
        }
    }
}

template <int D>
void ParticleExchange<D>::removeGhosts(ParticleFields<D>& fields)
{
    if (ghostCount_ > 0)
    {
        keepOnly(fields, owned_);
    }
    owned_.clear();
    sendTo_.clear();
    receiveAt_.clear();
    ghostCount_ = 0;
}

template <int D>
void ParticleExchange<D>::keepOnly(ParticleFields<D>& fields, const std::vector<std::uint8_t>& keep)
{
    if (keep.size() != fields.size())
    {
        throw std::logic_error("ParticleExchange::keepOnly: one flag per local particle");
    }
    // Compacts in place: a kept particle only moves down (its new index is at most its old).
    double value[D * D * D];
    std::size_t kept = 0;
    for (auto& field : fields.all())
    {
        if (!field.array->stored())
        {
            continue;
        }
        kept = 0;
        for (std::size_t a = 0; a < keep.size(); ++a)
        {
            if (keep[a])
            {
                if (kept != a)
                {
                    field.array->get(a, value);
                    field.array->set(kept, value);
                }
                ++kept;
            }
        }
    }
    for (RaggedArray* array : fields.ragged())
    {
        array->keepOnly(keep);
    }
    kept = static_cast<std::size_t>(std::count_if(keep.begin(), keep.end(),
                                                   [](std::uint8_t k) { return k != 0; }));
    fields.resize(kept);
    owned_.clear();
    sendTo_.clear();
    receiveAt_.clear();
    ownedCount_ = kept;
    ghostCount_ = 0;
}

template class ParticleExchange<1>;
template class ParticleExchange<2>;
template class ParticleExchange<3>;

} // namespace sph
