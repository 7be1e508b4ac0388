#pragma once
// The per-sample history of the gradient-of-F scheme with a material that keeps one
// (docs/theory/plasticity.md §P7): the stress sample F_b(a) = F_a + G_a x^r_ba of each pair
// a–b keeps its own committed state, as a finite element's quadrature point does, so that the
// commit lowers the scheme's energy by exactly the sampled dissipation.
//
// The states lie along the reference neighbour list (slot k of the list holds the sample of
// the pair it names), packed as the material packs them (Material::packHistory). A commit
// takes the states the last force evaluation computed (`next`). When the list changes (the
// updated-Lagrangian reference is rebuilt), follow() moves each state to the pair's new slot;
// a pair that is new starts from its owner's committed particle state (= its own sample a–a).
// The states and the layout they lie along are restart arrays, so a restart remaps them onto
// the list it rebuilds (the same list: the remap is then a copy).

#include "core/RunScalars.hpp"
#include "materials/Material.hpp"
#include "particles/NeighbourList.hpp"
#include "particles/Parallel.hpp"

#include <algorithm>
#include <vector>

namespace sph
{

template <int D>
class SampleHistory
{
public:
    // Active when some material has history: numbers per state = the largest of them.
    void declare(const std::vector<const Material<D>*>& materials, RunScalars& scalars)
    {
        for (const Material<D>* material : materials)
        {
            stride_ = std::max(stride_, material->historyComponents());
        }
        if (stride_ > 0)
        {
            scalars.bindArray("sampleHistory", states_);
            scalars.bindArray("sampleHistoryOffsets", offsets_);
            scalars.bindArray("sampleHistoryNeighbours", neighbours_);
        }
    }
    bool active() const { return stride_ > 0; }
    std::size_t stride() const { return stride_; }

    // The reference neighbour list was rebuilt: follow() it before the next evaluation.
    void listChanged() { current_ = false; }

    // Lays the states out along `list` (a no-op while it has not changed).
    void follow(const NeighbourList& list, const std::vector<int>& body,
                const std::vector<const Material<D>*>& materials)
    {
        if (current_ || !active())
        {
            return;
        }
        const std::size_t n = list.particleCount();
        const bool hadLayout = offsets_.size() == n + 1 &&
                               static_cast<std::size_t>(offsets_[n]) == neighbours_.size() &&
                               neighbours_.size() * stride_ == states_.size();
        // Into a buffer kept between moves (no allocation, no page faults once grown: the
        // reference moves every step). Slots of bodies without history are never read.
        resizePairArray(remapped_, list.pairCount() * stride_);
#pragma omp parallel if (useThreads(n))
        {
            std::vector<double> owner(stride_, 0.0);
#pragma omp for schedule(static)
            for (std::size_t a = 0; a < n; ++a)
            {
                const Material<D>* material = materials[static_cast<std::size_t>(body[a])];
                if (material->historyComponents() == 0)
                {
                    continue;
                }
                material->packHistory(a, owner.data());
                std::size_t old = hadLayout ? static_cast<std::size_t>(offsets_[a]) : 0;
                const std::size_t oldEnd = hadLayout ? static_cast<std::size_t>(offsets_[a + 1]) : 0;
                for (std::size_t k = list.begin(a); k < list.end(a); ++k)
                {
                    // Both lists: a itself first, then its neighbours in increasing index order.
                    const double b = list.indices[k];
                    const bool self = k == list.begin(a);
                    while (!self && old < oldEnd && (old == offsets_[a] || neighbours_[old] < b))
                    {
                        ++old;
                    }
                    const bool kept = old < oldEnd && neighbours_[old] == b;
                    const double* from = kept ? &states_[old * stride_] : owner.data();
                    std::copy(from, from + stride_, &remapped_[k * stride_]);
                }
            }
        }
        states_.swap(remapped_);
        resizePairArray(next_, states_.size()); // every slot of a history body is written before a commit
        offsets_.assign(list.offsets.begin(), list.offsets.end());
        neighbours_.assign(list.indices.begin(), list.indices.end());
        current_ = true;
    }

    // The committed states of the samples in slots k, k+1, ... and where the evaluation puts
    // the states a commit would make of them.
    const double* committed(std::size_t k) const { return &states_[k * stride_]; }
    double* next(std::size_t k) { return &next_[k * stride_]; }

    // The states of the last evaluation become the committed ones.
    void commit() { states_.swap(next_); }

private:
    std::size_t stride_ = 0;
    bool current_ = false;
    std::vector<double> states_;
    std::vector<double> next_;
    std::vector<double> remapped_; // follow()'s buffer
    // The list the states lie along (doubles: a restart array; indices < 2^32 are exact).
    std::vector<double> offsets_;
    std::vector<double> neighbours_;
};

} // namespace sph
