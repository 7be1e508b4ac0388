// `repulsion`: the seed's contact between bodies, eqs. (37)-(38) as corrected in spec §9/§12.
// For a particle a of body A near particles b of the other bodies,
//   R_a = κ Σ_b V_b W_ab / Σ_á V_á W_aá            (á: A's own particles, a included),
//   Δv_a = -Δt Σ_b m_b (R_a/ρ_a² + R_b/ρ_b²) ∇W_ab  (∇W_ab points from b to a: repulsive),
// in the current configuration x^{n+1}, with V = V0 J, ρ = ρ0/J, the solid's kernel and h, and
// applied to v^{n+1/2} after the leapfrog update. The pair terms are equal and opposite, so
// momentum is conserved; the energy it adds or removes is reported as contact work.
// Only pairs of bodies whose bounding boxes, grown by the kernel support, overlap are searched,
// and only their particles in the overlap: separated bodies cost a bounding box per step.
// Keys:
//   kappa | coefficient κ of eq. (37), a contact pressure [Pa]          | required
//   pairs | which bodies may touch, e.g. ((ringA ringB)); () = every pair | ()
#include "contact/Contact.hpp"
#include "core/InputError.hpp"
#include "particles/NeighbourList.hpp"
#include "particles/Parallel.hpp"

#include <algorithm>
#include <set>

namespace sph
{

template <int D>
class Repulsion : public Contact<D>
{
public:
    static std::string description()
    {
        return "Seed eqs. (37)-(38) (spec §9): repulsive velocity kick between particles of "
               "different bodies, coefficient kappa; searches only bodies whose grown bounding "
               "boxes overlap.";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::real("kappa", "coefficient kappa of seed eq. (37), a contact pressure [Pa]")
                     .positive())
            .add(Key::bodyList("pairs", "which bodies may touch, as a flat list of name pairs, "
                                        "e.g. (ringA ringB); () = every pair")
                     .defaultValue("()"));
    }

    Repulsion(const Params& params, const typename Contact<D>::Args& args)
        : kernel_(*args.kernel), kappa_(params.real("kappa"))
    {
        const auto& pairs = params.wordList("pairs");
        if (pairs.size() % 2 != 0)
        {
            params.fail("pairs", "repulsion: 'pairs' must list body names two by two",
                        {"e.g. pairs (ringA ringB ringA wall);"});
        }
        const std::size_t bodies = args.bodyNames.size();
        allowed_.assign(bodies, std::vector<std::uint8_t>(bodies, pairs.empty() ? 1 : 0));
        const std::vector<std::size_t> index = params.bodyIndices("pairs");
        for (std::size_t i = 0; i + 1 < pairs.size(); i += 2)
        {
            const std::size_t A = index[i];
            const std::size_t B = index[i + 1];
            if (A == B)
            {
                params.fail("pairs", i + 1, "repulsion: a body cannot be in contact with itself");
            }
            allowed_[A][B] = allowed_[B][A] = 1;
        }
    }

    bool active() const override { return true; }
    double reach() const override { return kernel_.supportRadius(); }
    std::size_t pairsSearched() const override { return pairsSearched_; }

    void apply(ContactState<D>& state, std::vector<Vec<D>>& deltaV) override
    {
        const ParticleSet<D>& p = state.particles;
        const ParticleRanks* ranks = state.ranks;
        const std::size_t bodies = p.bodies.size();
        deltaV.assign(p.size(), Vec<D>::Zero());
        pairsSearched_ = 0;
        if (bodies < 2)
        {
            return;
        }
        const double reach = kernel_.supportRadius();
        // 1. Bounding boxes of the bodies, grown by the kernel support.
        std::vector<Vec<D>> lower(bodies, Vec<D>::Constant(std::numeric_limits<double>::max()));
        std::vector<Vec<D>> upper(bodies, Vec<D>::Constant(std::numeric_limits<double>::lowest()));
        for (std::size_t b = 0; b < bodies; ++b)
        {
            double low[D];
            double high[D];
            for (int d = 0; d < D; ++d)
            {
                low[d] = std::numeric_limits<double>::max();
                high[d] = std::numeric_limits<double>::lowest();
            }
            const std::size_t first = p.bodies[b].begin;
            const std::size_t last = p.bodies[b].end;
            // Minima and maxima do not depend on the order: parallel and deterministic.
#pragma omp parallel for schedule(static) reduction(min : low[:D]) reduction(max : high[:D]) \
    if (useThreads(last - first))
            for (std::size_t a = first; a < last; ++a)
            {
                if (ranks && !ranks->counts(a))
                {
                    continue; // each particle counts once, at its owner
                }
                for (int d = 0; d < D; ++d)
                {
                    low[d] = std::min(low[d], state.x[a][d]);
                    high[d] = std::max(high[d], state.x[a][d]);
                }
            }
            for (int d = 0; d < D; ++d)
            {
                lower[b][d] = low[d];
                upper[b][d] = high[d];
            }
        }
        if (ranks)
        {
            agreeOnBoxes(*ranks, lower, upper);
        }
        for (std::size_t b = 0; b < bodies; ++b)
        {
            lower[b].array() -= reach;
            upper[b].array() += reach;
        }
        // 2. Pairs that can touch, and the particles in their overlap.
        std::vector<std::uint8_t> involved(p.size(), 0);
        std::vector<std::vector<std::uint8_t>> touching(bodies, std::vector<std::uint8_t>(bodies, 0));
        for (std::size_t A = 0; A < bodies; ++A)
        {
            for (std::size_t B = A + 1; B < bodies; ++B)
            {
                if (!allowed_[A][B] || (lower[A].array() > upper[B].array()).any() ||
                    (lower[B].array() > upper[A].array()).any())
                {
                    continue;
                }
                ++pairsSearched_;
                touching[A][B] = touching[B][A] = 1;
                const Vec<D> low = lower[A].cwiseMax(lower[B]);
                const Vec<D> high = upper[A].cwiseMin(upper[B]);
                for (const std::size_t body : {A, B})
                {
                    for (std::size_t a = p.bodies[body].begin; a < p.bodies[body].end; ++a)
                    {
                        // Inside the overlap grown once more: own-body neighbours of the
                        // particles in the overlap count in Σ_á V_á W_aá.
                        if ((state.x[a].array() >= low.array() - reach).all() &&
                            (state.x[a].array() <= high.array() + reach).all())
                        {
                            involved[a] = (state.x[a].array() >= low.array()).all() &&
                                                  (state.x[a].array() <= high.array()).all()
                                              ? 2
                                              : std::max<std::uint8_t>(involved[a], 1);
                        }
                    }
                }
            }
        }
        if (pairsSearched_ == 0)
        {
            return;
        }
        // 3. Neighbours of the particles in the overlaps among all nearby particles.
        std::vector<std::size_t> queries;
        std::vector<std::size_t> sources;
        for (std::size_t a = 0; a < p.size(); ++a)
        {
            if (involved[a])
            {
                sources.push_back(a);
                if (involved[a] == 2)
                {
                    queries.push_back(a);
                }
            }
        }
        std::vector<Vec<D>> queryX(queries.size());
        std::vector<Vec<D>> sourceX(sources.size());
        for (std::size_t i = 0; i < queries.size(); ++i)
        {
            queryX[i] = state.x[queries[i]];
        }
        for (std::size_t i = 0; i < sources.size(); ++i)
        {
            sourceX[i] = state.x[sources[i]];
        }
        const NeighbourList list = buildCrossNeighbourList<D>(queryX, sourceX, reach);
        // 4. R_a = κ Σ_b V_b W_ab / Σ_á V_á W_aá with V = V0 J at x^{n+1}, once per particle.
        // Distributed: a ghost's J reads its neighbours in the reference configuration, which
        // only its owner holds whole; the owner computes it (the boxes are the serial ones, so
        // a ghost that is a source here is one at its owner too) and shares it.
        std::vector<double> currentVolume(p.size(), 0.0);
#pragma omp parallel for schedule(static) if (useThreads(sources.size()))
        for (std::size_t i = 0; i < sources.size(); ++i)
        {
            const std::size_t a = sources[i];
            currentVolume[a] = !ranks || ranks->counts(a) ? p.V0[a] * state.jacobian(a) : 0.0;
        }
        if (ranks)
        {
            ranks->shareWithGhosts(currentVolume);
        }
        const auto volume = [&](std::size_t a) { return currentVolume[a]; };
        const std::size_t nq = queries.size();
        std::vector<double> R(p.size(), 0.0);
#pragma omp parallel for schedule(static) if (useThreads(nq))
        for (std::size_t i = 0; i < nq; ++i)
        {
            const std::size_t a = queries[i];
            double own = 0.0;
            double other = 0.0;
            for (std::size_t k = list.begin(i); k < list.end(i); ++k)
            {
                const std::size_t b = sources[list.indices[k]];
                const double w = volume(b) * kernel_.W((state.x[a] - state.x[b]).norm());
                if (p.body[b] == p.body[a])
                {
                    own += w;
                }
                else if (touching[static_cast<std::size_t>(p.body[a])][static_cast<std::size_t>(p.body[b])])
                {
                    other += w;
                }
            }
            R[a] = own > 0.0 ? kappa_ * other / own : 0.0;
        }
        // 5. Δv_a = -Δt Σ_b m_b (R_a/ρ_a² + R_b/ρ_b²) ∇W_ab, gathered per particle.
#pragma omp parallel for schedule(static) if (useThreads(nq))
        for (std::size_t i = 0; i < nq; ++i)
        {
            const std::size_t a = queries[i];
            if (p.fixed[a] || R[a] == 0.0)
            {
                continue;
            }
            const double rhoA = p.m[a] / volume(a);
            Vec<D> sum = Vec<D>::Zero();
            for (std::size_t k = list.begin(i); k < list.end(i); ++k)
            {
                const std::size_t b = sources[list.indices[k]];
                if (p.body[b] == p.body[a] ||
                    !touching[static_cast<std::size_t>(p.body[a])][static_cast<std::size_t>(p.body[b])])
                {
                    continue;
                }
                const Vec<D> r = state.x[a] - state.x[b];
                const double distance = r.norm();
                if (distance <= 0.0)
                {
                    continue;
                }
                const double rhoB = p.m[b] / volume(b);
                const Vec<D> gradW = (kernel_.dWdr(distance) / distance) * r;
                sum += p.m[b] * (R[a] / (rhoA * rhoA) + R[b] / (rhoB * rhoB)) * gradW;
            }
            deltaV[a] = -state.deltaT * sum;
        }
        for (const std::size_t a : queries)
        {
            state.v[a] += deltaV[a];
        }
    }

private:
    // The bodies' boxes over every rank's owned particles: those of the serial run, bit for bit
    // (a minimum or maximum does not depend on the order), so every rank searches the same pairs.
    static void agreeOnBoxes(const ParticleRanks& ranks, std::vector<Vec<D>>& lower,
                             std::vector<Vec<D>>& upper)
    {
        std::vector<double> low;
        std::vector<double> high;
        for (std::size_t b = 0; b < lower.size(); ++b)
        {
            low.insert(low.end(), lower[b].data(), lower[b].data() + D);
            high.insert(high.end(), upper[b].data(), upper[b].data() + D);
        }
        ranks.minimum(low);
        ranks.maximum(high);
        for (std::size_t b = 0; b < lower.size(); ++b)
        {
            std::copy_n(&low[b * D], D, lower[b].data());
            std::copy_n(&high[b * D], D, upper[b].data());
        }
    }

    const Kernel& kernel_;
    double kappa_;
    std::vector<std::vector<std::uint8_t>> allowed_;
    std::size_t pairsSearched_ = 0;
};

SPH_REGISTER_DIM_MODEL(Contact, Repulsion, "repulsion");

} // namespace sph
