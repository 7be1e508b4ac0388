#pragma once
// The per-sample history of the gradient-of-F scheme with a material that keeps one
// (docs/theory/plasticity.md §P7): the stress sample F_b(a) = F_a + G_a x^r_ba of each pair
// a–b keeps its own committed state, as a finite element's quadrature point does, so that the
// commit lowers the scheme's energy by exactly the sampled dissipation.
//
// The states lie along the reference neighbour list (slot k of the list holds the sample of
// the pair it names), packed as the material packs them (Material::packHistory), each with the
// global index of the neighbour it samples. A commit takes the states the last force
// evaluation computed (`next`). When the list changes (the updated-Lagrangian reference is
// rebuilt, or a distributed run's local particles change), follow() moves each state to the
// pair's new slot by the neighbour's global index; a pair that is new starts from its owner's
// committed particle state (= its own sample a–a).
//
// To the field registry the states are a ragged particle field (particles/RaggedArray.hpp):
// particle a's entries are its samples, each [neighbour's global index, state]. So they move
// with their particle between ranks (a ghost gets its owner's states when it is gathered, and
// commits them itself, as it does its particle history), and they are restart data; a
// restart, or an exchange, leaves them in particle order, and follow() lays them out along the
// list again.
//
// With energy weights (gradF's moveWeights, docs/theory/gradF-plastic.md §G9) each sample also
// carries its energy weight ω_ab, chosen at the last move and kept with the pair (a pair new at
// a move starts with 0, a first layout with none: NaN, the kernel's). The samples that leave
// the list at a move are set aside, with their weights and states, for the evaluation that
// follows the move: their energy is part of what the old reference held.

#include "materials/Material.hpp"
#include "particles/NeighbourList.hpp"
#include "particles/Parallel.hpp"
#include "particles/ParticleFields.hpp"

#include <algorithm>
#include <limits>
#include <vector>

namespace sph
{

template <int D>
class SampleHistory final : public RaggedArray
{
public:
    // Active when some material has history: numbers per state = the largest of them.
    void declare(const std::vector<const Material<D>*>& materials, ParticleFields<D>& fields,
                 bool weighted = false)
    {
        weighted_ = weighted;
        for (const Material<D>* material : materials)
        {
            stride_ = std::max(stride_, material->historyComponents());
        }
        if (stride_ > 0)
        {
            assign(std::vector<std::size_t>(fields.size(), 0), {});
            fields.bindRagged(*this);
        }
    }
    bool active() const { return stride_ > 0; }
    bool weighted() const { return weighted_; }
    // Whether the states are laid out along the list last followed (and it has not changed).
    bool current() const { return current_; }
    std::size_t stride() const { return stride_; }

    // The reference neighbour list was rebuilt: follow() it before the next evaluation.
    void listChanged() { current_ = false; }

    // Lays the states out along `list` (a no-op while it has not changed). globalId: each
    // local particle's global index (null: its index). A new pair a–b starts from a's own
    // state, or, given the reference gradients Fr, from b's own state expressed at a (its be
    // kept: Material::rebaseHistory from Fr_b to Fr_a; docs/theory/gradF-plastic.md §G4) when b
    // is of the same material and a had samples before (the first layout starts from a's).
    void follow(const NeighbourList& list, const std::vector<int>& body,
                const std::vector<const Material<D>*>& materials, const std::vector<int>* globalId,
                const std::vector<Mat<D>>* Fr = nullptr)
    {
        if (current_ || !active())
        {
            return;
        }
        const std::size_t n = list.particleCount();
        if (offsets_.size() != n + 1)
        {
            throw std::logic_error("SampleHistory: the states are of " + std::to_string(size()) +
                                   " particles, the list of " + std::to_string(n));
        }
        const auto global = [globalId](std::size_t b) {
            return globalId ? static_cast<double>((*globalId)[b]) : static_cast<double>(b);
        };
        // Into a buffer kept between moves (no allocation, no page faults once grown: the
        // reference moves every step). Slots of bodies without history are never read.
        resizePairArray(remapped_, list.pairCount() * stride_);
        if (weighted_)
        {
            remappedWeights_.resize(list.pairCount());
            keptOld_.assign(neighbours_.size(), 0);
        }
#pragma omp parallel if (useThreads(n))
        {
            std::vector<double> owner(stride_, 0.0);
            std::vector<double> neighbour(stride_, 0.0);
#pragma omp for schedule(static)
            for (std::size_t a = 0; a < n; ++a)
            {
                const Material<D>* material = materials[static_cast<std::size_t>(body[a])];
                if (material->historyComponents() == 0)
                {
                    continue;
                }
                material->packHistory(a, owner.data());
                std::size_t old = offsets_[a];
                const std::size_t oldEnd = offsets_[a + 1];
                for (std::size_t k = list.begin(a); k < list.end(a); ++k)
                {
                    // Both: a itself first, then its neighbours in increasing global index
                    // (local particles are in increasing global index).
                    const double b = global(list.indices[k]);
                    const bool self = k == list.begin(a);
                    while (!self && old < oldEnd && (old == offsets_[a] || neighbours_[old] < b))
                    {
                        ++old;
                    }
                    const bool kept = old < oldEnd && neighbours_[old] == b;
                    const double* from = kept ? &states_[old * stride_] : owner.data();
                    const std::size_t local = list.indices[k];
                    if (weighted_)
                    {
                        const bool firstLayout = oldEnd == offsets_[a];
                        remappedWeights_[k] = kept          ? weights_[old]
                                              : firstLayout ? std::numeric_limits<double>::quiet_NaN()
                                                            : 0.0;
                        if (kept)
                        {
                            keptOld_[old] = 1;
                        }
                    }
                    // (A particle with no states yet is being laid out for the first time:
                    // its samples start virgin, as its own state does.)
                    if (!kept && !self && Fr && oldEnd > offsets_[a] &&
                        materials[static_cast<std::size_t>(body[local])] == material)
                    {
                        material->packHistory(local, neighbour.data());
                        material->rebaseHistory(neighbour.data(), (*Fr)[local], (*Fr)[a]);
                        from = neighbour.data();
                    }
                    std::copy(from, from + stride_, &remapped_[k * stride_]);
                }
            }
        }
        if (weighted_)
        {
            setAsideLeaving(body, materials);
            weights_.swap(remappedWeights_);
        }
        states_.swap(remapped_);
        resizePairArray(next_, states_.size()); // every slot of a history body is written before a commit
        offsets_.assign(list.offsets.begin(), list.offsets.end());
        neighbours_.resize(list.indices.size());
        for (std::size_t k = 0; k < neighbours_.size(); ++k)
        {
            neighbours_[k] = global(list.indices[k]);
        }
        current_ = true;
    }

    // The committed states of the samples in slots k, k+1, ... and where the evaluation puts
    // the states a commit would make of them.
    const double* committed(std::size_t k) const { return &states_[k * stride_]; }
    double* next(std::size_t k) { return &next_[k * stride_]; }
    // The committed state in slot k, to be re-expressed when the reference moves (§G4).
    double* committedForMove(std::size_t k) { return &states_[k * stride_]; }

    // Energy weights (weighted() only): of slot k; and the samples particle a lost at the last
    // follow(): count, their weights and their states (stride() numbers each).
    double& weight(std::size_t k) { return weights_[k]; }
    std::size_t leavingCount(std::size_t a) const
    {
        return leavingOffsets_.empty() ? 0 : leavingOffsets_[a + 1] - leavingOffsets_[a];
    }
    const double* leavingWeights(std::size_t a) const { return &leavingWeights_[leavingOffsets_[a]]; }
    const double* leavingStates(std::size_t a) const
    {
        return &leavingStates_[leavingOffsets_[a] * stride_];
    }
    // The evaluation after the move has used them.
    void clearLeaving() { leavingOffsets_.clear(); }

    // The states of the last evaluation become the committed ones.
    void commit() { states_.swap(next_); }

    // The ragged field: particle a's samples, each [neighbour's global index, state].
    const std::string& name() const override { return name_; }
    std::size_t width() const override { return 1 + stride_ + (weighted_ ? 1 : 0); }
    std::size_t size() const override { return offsets_.empty() ? 0 : offsets_.size() - 1; }
    std::size_t entries(std::size_t a) const override { return offsets_[a + 1] - offsets_[a]; }
    void get(std::size_t a, double* out) const override
    {
        for (std::size_t k = offsets_[a]; k < offsets_[a + 1]; ++k)
        {
            *out++ = neighbours_[k];
            out = std::copy(&states_[k * stride_], &states_[(k + 1) * stride_], out);
            if (weighted_)
            {
                *out++ = weights_[k];
            }
        }
    }
    void assign(const std::vector<std::size_t>& counts, std::vector<double> values) override
    {
        offsets_.assign(counts.size() + 1, 0);
        for (std::size_t a = 0; a < counts.size(); ++a)
        {
            offsets_[a + 1] = offsets_[a] + counts[a];
        }
        const std::size_t pairs = offsets_.back();
        if (values.size() != pairs * width())
        {
            throw std::logic_error("SampleHistory: " + std::to_string(values.size()) +
                                   " numbers for " + std::to_string(pairs) + " samples");
        }
        neighbours_.resize(pairs);
        states_.resize(pairs * stride_);
        weights_.resize(weighted_ ? pairs : 0);
        for (std::size_t k = 0; k < pairs; ++k)
        {
            const double* in = &values[k * width()];
            neighbours_[k] = in[0];
            std::copy(in + 1, in + 1 + stride_, &states_[k * stride_]);
            if (weighted_)
            {
                weights_[k] = in[1 + stride_];
            }
        }
        current_ = false;
    }

private:
    // The old slots follow() did not keep, of particles with history that had samples: their
    // weights and states, by particle (before the old layout is dropped).
    void setAsideLeaving(const std::vector<int>& body, const std::vector<const Material<D>*>& materials)
    {
        const std::size_t n = offsets_.size() - 1;
        leavingOffsets_.assign(n + 1, 0);
        leavingWeights_.clear();
        leavingStates_.clear();
        for (std::size_t a = 0; a < n; ++a)
        {
            if (materials[static_cast<std::size_t>(body[a])]->historyComponents() > 0)
            {
                for (std::size_t old = offsets_[a]; old < offsets_[a + 1]; ++old)
                {
                    if (!keptOld_[old])
                    {
                        leavingWeights_.push_back(weights_[old]);
                        leavingStates_.insert(leavingStates_.end(), &states_[old * stride_],
                                              &states_[(old + 1) * stride_]);
                    }
                }
            }
            leavingOffsets_[a + 1] = leavingWeights_.size();
        }
    }

    std::string name_ = "sampleHistory";
    bool weighted_ = false;
    std::vector<double> weights_;
    std::vector<double> remappedWeights_;
    std::vector<char> keptOld_;
    std::vector<std::size_t> leavingOffsets_;
    std::vector<double> leavingWeights_;
    std::vector<double> leavingStates_;
    std::size_t stride_ = 0;
    bool current_ = false;
    std::vector<double> states_;
    std::vector<double> next_;
    std::vector<double> remapped_; // follow()'s buffer
    // The samples of particle a are slots offsets_[a] .. offsets_[a + 1]: a itself first, then
    // its neighbours, by global index (a double: exact below 2^53).
    std::vector<std::size_t> offsets_;
    std::vector<double> neighbours_;
};

} // namespace sph
