#pragma once
// The per-sample history of the gradient-of-F scheme with a material that keeps one
// (docs/theory/plasticity.md §P7): the stress sample F_b(a) = F_a + G_a x^r_ba of each pair
// a–b keeps its own committed state, as a finite element's quadrature point does, so that the
// commit lowers the scheme's energy by exactly the sampled dissipation.
//
// The samples lie along the reference neighbour list (slot k of the list is the sample of the
// pair it names), each with the global index of the neighbour it samples. A sample in the
// material's initial state (one that never flowed: most of a body, most of the time) stores
// nothing; the others keep their state in a pool (StatePool), in the material's compact form
// (Material::compactHistory: Cp⁻¹ is symmetric), slot k naming its record. An evaluation reads
// a particle's states unpacked (read()) and hands back the states a commit would make of them
// (keepPending()): only those that differ from the committed ones, or that the material says
// changed (it flowed), are kept, and the commit writes them in place. When the list changes
// (the updated-Lagrangian reference is rebuilt, or a distributed run's local particles change),
// follow() moves each state to the pair's new slot by the neighbour's global index; a pair
// that is new starts from its owner's committed particle state (= its own sample a–a).
//
// follow() and its helpers are defined in SampleHistoryLayout.hpp (the layout per particle in
// SampleHistoryPerParticle.hpp), what an evaluation reads and hands back (readRows(),
// keepPending(), commit()) in SampleHistoryEvaluation.hpp, what a move does to the states
// (storeEveryState(), rebase(), setState()) in SampleHistoryRebase.hpp, all included at the end.
//
// To the field registry the states are a ragged particle field (particles/RaggedArray.hpp):
// particle a's entries are its samples, each [neighbour's global index, packed state]. So they
// move with their particle between ranks (a ghost gets its owner's states when it is gathered,
// and commits them itself, as it does its particle history), and they are restart data; a
// restart, or an exchange, leaves them in particle order, and follow() lays them out along the
// list again.
//
// Laid out per particle (declare()'s perParticle > 0: gradF's moment points in updated
// Lagrangian form, docs/theory/gradF-moments.md §M7), every particle has that many samples,
// whatever its neighbours: sample q is the particle's point q across moves, the list does not
// lay them out, and the ragged field (named momentPointHistory, so that neither layout reads
// the other's restart data) holds q in place of a neighbour's index.
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
#include "stabilisation/gradF/PendingStates.hpp"
#include "stabilisation/gradF/StatePool.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace sph
{

template <int D> class SampleHistory final : public RaggedArray
{
public:
    // Active when some material has history. The materials with history share one packed
    // layout (every plastic material: PlasticState), which the restart field is written in.
    void declare(const std::vector<const Material<D>*>& materials, ParticleFields<D>& fields,
                 bool weighted = false, std::size_t perParticle = 0)
    {
        weighted_ = weighted;
        perParticle_ = perParticle;
        if (perParticle_ > 0)
        {
            name_ = "momentPointHistory";
        }
        for (const Material<D>* material : materials)
        {
            if (material->historyComponents() == 0)
            {
                continue;
            }
            if (codec_ && material->historyComponents() != stride_)
            {
                throw std::logic_error("SampleHistory: materials with histories of different "
                                       "layouts");
            }
            // One packed layout, compact forms that may keep more or less of it (druckerPrager
            // keeps its flow pressure, j2Plasticity not): the widest keeps every state.
            if (codec_ && material->compactHistoryComponents() <= pool_.width())
            {
                continue;
            }
            codec_ = material;
            stride_ = material->historyComponents();
            if (stride_ > maxStride)
            {
                throw std::logic_error("SampleHistory: a history of more than " +
                                       std::to_string(maxStride) + " numbers");
            }
            pool_.reset(material->compactHistoryComponents());
            initial_.resize(stride_);
            material->packInitialHistory(initial_.data());
            initialCompact_.resize(pool_.width());
            compact(initial_.data(), initialCompact_.data());
            learnExpansion();
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
    // The first slot of particle a's samples (after follow(): along the list, its begin(a)).
    std::size_t begin(std::size_t a) const { return offsets_[a]; }
    // The samples of each particle when laid out per particle (else 0: along the list).
    std::size_t perParticle() const { return perParticle_; }

    // Lays the states out along `list` (a no-op while it has not changed). globalId: each
    // local particle's global index (null: its index). A new pair a–b starts from a's own
    // state, or, given the reference gradients Fr, from b's own state expressed at a (its be
    // kept: Material::rebaseHistory from Fr_b to Fr_a; docs/theory/gradF-plastic.md §G4) when b
    // is of the same material and a had samples before (the first layout starts from a's).
    void follow(const NeighbourList& list, const std::vector<int>& body,
                const std::vector<const Material<D>*>& materials, const std::vector<int>* globalId,
                const std::vector<Mat<D>>* Fr = nullptr);

    // The committed states of the samples in slots first .. first + count, unpacked into
    // `out` (stride() numbers each).
    void read(std::size_t first, std::size_t count, double* out) const
    {
        for (std::size_t j = 0; j < count; ++j)
        {
            readSlot(first + j, out + j * stride_);
        }
    }
    // The same in rows (HistoryOf::samplesInRows): component c of slot first + j at
    // out[c * rowLength + j], rowLength ≥ count; the entries past count, up to padTo (≤
    // rowLength; all of the row by default), hold the initial state. (Most samples have no
    // record: their rows are the initial state's, written a row at a time.) Several particles'
    // samples side by side in one set of rows: each read at its offset in the rows (out + offset)
    // with padTo = rowLength - offset, in the order of the offsets.
    void readRows(std::size_t first, std::size_t count, double* out, std::size_t rowLength) const
    {
        readRows(first, count, out, rowLength, rowLength);
    }
    void readRows(std::size_t first, std::size_t count, double* out, std::size_t rowLength,
                  std::size_t padTo) const;
    // What an evaluation found a commit would make of the states of slots first .. first +
    // count (`next`, packed, stride() numbers each): the states that differ from the committed
    // ones (compared in their compact forms, which are exact) are kept for the commit. The last
    // evaluation's are the ones committed; clearPending() before it starts. changed (if not
    // null): HistoryOf's, 0 where next is the committed state and was not written; a sample
    // with a record that it marks 1 is kept without the comparison (the commit then writes its
    // numbers, whether or not they changed).
    void keepPending(std::size_t first, std::size_t count, const double* next,
                     const std::uint8_t* changed = nullptr);
    // Whether the records lie in the order of the slots that name them (what a relocation
    // leaves; for the tests).
    bool recordsInSlotOrder() const;
    // The record of slots first .. first + count, if every one has a record and they lie side
    // by side in slot order (readRows() copies them a row at a time); else null. (Only where
    // the codec's expansion is a copy. Public for the tests.)
    const double* fromOneRun(std::size_t first, std::size_t count) const;
    // A force evaluation starts: what the last one kept is no longer the state to commit.
    void clearPending() { pending_.clear(pool_.width()); }
    // The last evaluation's pending states set aside while other evaluations come (the
    // operator probe's), and put back for the commit.
    void setAsidePending() { pending_.setAside(); }
    void restorePending() { pending_.restore(); }
    // The states of the last evaluation become the committed ones, in place: first a record
    // for each sample that had none (the pool grows, one thread), then the copies, each
    // evaluating thread's list by a thread (the lists name distinct slots). The records are
    // then put back in slot order once more than 1/relocateAfter of them are new since they
    // last were: a list that never changes (total Lagrangian) is never follow()ed again, and
    // its records would stay in the order the samples first flowed.
    void commit();

    // Every sample of a particle with history gets a record of its own (a move of the
    // reference is about to re-express them all in place: rebase()).
    // (materials by body: Material<D>* or const Material<D>*, null for a body without history.)
    template <class Materials>
    void storeEveryState(const std::vector<int>& body, const Materials& materials);
    // The committed states in slots first .. first + count re-expressed when the reference
    // moves (§G4): the be of the sample in slot first + j at `to` is the one it had at
    // from[j] (after storeEveryState()). buffer: count · stride() numbers.
    void rebase(std::size_t first, std::size_t count, const Material<D>& material,
                const Mat<D>* from, const Mat<D>& to, double* buffer);
    // The committed state of slot k (which has a record: storeEveryState()) set to `packed`
    // (gradF's openedSamples particle at a move, §G22).
    void setState(std::size_t k, const double* packed);

    // Energy weights (weighted() only): of slot k; and the samples particle a lost at the last
    // follow(): count, their weights and their states (stride() numbers each).
    double& weight(std::size_t k) { return weights_[k]; }
    std::size_t leavingCount(std::size_t a) const
    {
        return leavingOffsets_.empty() ? 0 : leavingOffsets_[a + 1] - leavingOffsets_[a];
    }
    const double* leavingWeights(std::size_t a) const
    {
        return &leavingWeights_[leavingOffsets_[a]];
    }
    const double* leavingStates(std::size_t a) const
    {
        return &leavingStates_[leavingOffsets_[a] * stride_];
    }
    // The evaluation after the move has used them.
    void clearLeaving() { leavingOffsets_.clear(); }

    // The samples that keep a record (the rest are in the initial state).
    std::size_t storedStates() const { return pool_.held(); }

    // The ragged field: particle a's samples, each [neighbour's global index, packed state].
    const std::string& name() const override { return name_; }
    std::size_t width() const override { return 1 + stride_ + (weighted_ ? 1 : 0); }
    std::size_t size() const override { return offsets_.empty() ? 0 : offsets_.size() - 1; }
    std::size_t entries(std::size_t a) const override { return offsets_[a + 1] - offsets_[a]; }
    void get(std::size_t a, double* out) const override
    {
        for (std::size_t k = offsets_[a]; k < offsets_[a + 1]; ++k)
        {
            *out++ = neighbours_[k];
            readSlot(k, out);
            out += stride_;
            if (weighted_)
            {
                *out++ = weights_[k];
            }
        }
    }
    // (A restart, or an exchange: the states in particle order, laid out along the list by the
    // next follow(). Defined in SampleHistoryLayout.hpp.)
    void assign(const std::vector<std::size_t>& counts, std::vector<double> values) override;

    // The longest packed state a material may have (a caller's buffer for one).
    static constexpr std::size_t maxStride = 16;

private:
    // follow() and commit() relocate the records once more than 1/relocateAfter of them were
    // handed out since they were last in order (the cost of a relocation is one pass over the
    // records).
    static constexpr std::size_t relocateAfter = 8;
    // Slot markers of follow() (above any record StatePool hands out): a kept pair's old slot;
    // a new pair that starts from its neighbour's state, or from its owner's.
    static constexpr StatePool::Index moved = StatePool::none - 1;
    static constexpr StatePool::Index fromNeighbour = StatePool::none - 2;
    static constexpr StatePool::Index fromOwner = StatePool::none - 3;
    static bool isRecord(StatePool::Index slot) { return slot < fromOwner; }

    // (A loop over the numbers' bits, not memcmp: a state is a few numbers, compared for every
    // sample at every evaluation, and the library call cost more than the comparison.)
    static bool sameBits(const double* x, const double* y, std::size_t n)
    {
        std::uint64_t difference = 0;
        for (std::size_t k = 0; k < n; ++k)
        {
            difference |= std::bit_cast<std::uint64_t>(x[k]) ^ std::bit_cast<std::uint64_t>(y[k]);
        }
        return difference == 0;
    }
    bool sameBits(const double* x, const double* y) const { return sameBits(x, y, stride_); }
    bool isInitial(const double* state) const { return sameBits(state, initial_.data()); }
    void readSlot(std::size_t k, double* out) const
    {
        if (slot_[k] == StatePool::none)
        {
            std::copy(initial_.begin(), initial_.end(), out);
        }
        else
        {
            codec_->expandHistory(pool_.at(slot_[k]), out);
        }
    }
    // keepPending() with records of W numbers (W = 0: pool_.width(), known at run time only):
    // a compile-time width unrolls the compaction, comparison and copy of each state, which
    // otherwise were a virtual call and a call of the C library's memmove per sample.
    template <std::size_t W>
    void keepChanged(std::size_t first, std::size_t count, const double* next,
                     const std::uint8_t* changed, PendingStates::List& mine);
    // f(std::integral_constant<std::size_t, W>) with W the records' width where it is one of
    // the plastic materials' (5, 6 in 2D; 7, 8 in 3D), else W = 0.
    template <class F> void withRecordWidth(F&& f) const;
    // How the codec's expandHistory() fills a packed state, if it only copies: component c is
    // the compact form's expandFrom_[c], or (constant) expandConstant_[c]. Learnt by expanding
    // two compact forms of distinct numbers; expandFrom_ stays empty (readRows() then calls
    // the codec) where the expansion is anything else. (readRows() copies a record's numbers
    // straight into the rows, without a virtual call and a packed copy in between.) And its
    // inverse, if every compact number is copied somewhere: compact number k is the packed
    // state's compactFrom_[k] (keepPending() compacts by copies, and checks that they expand
    // back to the packed state bit for bit, as the codec's compactHistory() does:
    // compactsExactly()).
    static constexpr std::size_t constant = maxStride;
    void learnExpansion();
    // Whether compactFrom_'s copies of `packed` expand back to it bit for bit: the packed
    // numbers that are not copied (a symmetric Cp⁻¹'s lower triangle, a constant) are the ones
    // the expansion would give (learnExpansion()'s list, compactChecks_).
    struct CompactCheck
    {
        std::size_t at, sameAs; // packed[at] == packed[sameAs], or with sameAs == constant,
        double value;           // == value
    };
    bool compactsExactly(const double* packed) const;

    // The compact form of a packed state, which must unpack to it bit for bit.
    void compact(const double* state, double* out) const
    {
        if (!codec_->compactHistory(state, out))
        {
            throw std::runtime_error("sampleHistory: a state the material cannot keep exactly "
                                     "(its Cp^-1 is not symmetric: not written by sphSolid)");
        }
    }

    // The records laid out in the order of the slots that name them, so that an evaluation
    // (which reads them particle by particle) streams through the pool. Only where they are
    // stored changes: every state, and so every result, is the same.
    // (destination: a buffer for the records' new places, follow()'s, free again by then, or
    // commit()'s own.)
    void relocateInSlotOrder(std::vector<StatePool::Index>& destination);
    // Whether the records have decayed far enough from slot order to relocate them.
    bool relocationDue() const
    {
        return pool_.allocatedSinceOrdered() * relocateAfter > pool_.held();
    }

    // follow()'s new pairs that start from a state of their own, in slot order.
    void storeNewStates(const NeighbourList& list, const std::vector<int>& body,
                        const std::vector<const Material<D>*>& materials,
                        const std::vector<std::uint8_t>& hasNew, const std::vector<Mat<D>>* Fr);

    // The old slots follow() did not keep (not `moved`), of particles with history that had
    // samples: their weights and states, by particle (before the old layout is dropped).
    void setAsideLeaving(const std::vector<int>& body,
                         const std::vector<const Material<D>*>& materials);

    // follow() where the samples are laid out per particle (perParticle_ > 0).
    void layOutPerParticle(std::size_t n, const std::vector<int>& body,
                           const std::vector<const Material<D>*>& materials);

    std::string name_ = "sampleHistory";
    bool weighted_ = false;
    std::size_t perParticle_ = 0;
    std::vector<double> weights_;
    std::vector<std::size_t> leavingOffsets_;
    std::vector<double> leavingWeights_;
    std::vector<double> leavingStates_;
    std::size_t stride_ = 0;
    const Material<D>* codec_ = nullptr;  // packs and unpacks the states of every material
    std::vector<double> initial_;         // the initial state, packed
    std::vector<double> initialCompact_;  // and compact
    std::vector<std::size_t> expandFrom_; // learnExpansion()'s
    std::vector<double> expandConstant_;
    std::vector<std::size_t> compactFrom_;
    std::vector<std::size_t> identity_;   // 0, 1, ..., the records' width - 1
    std::vector<CompactCheck> compactChecks_;
    bool current_ = false;
    StatePool pool_;
    PendingStates pending_; // keepPending()'s, for commit()
    // The samples of particle a are slots offsets_[a] .. offsets_[a + 1]: a itself first, then
    // its neighbours, by global index. Slot k's record, or none (the initial state).
    std::vector<std::size_t> offsets_;
    std::vector<int> neighbours_;
    std::vector<StatePool::Index> slot_;
};

} // namespace sph

#include "stabilisation/gradF/SampleHistoryEvaluation.hpp"
#include "stabilisation/gradF/SampleHistoryLayout.hpp"
#include "stabilisation/gradF/SampleHistoryPerParticle.hpp"
#include "stabilisation/gradF/SampleHistoryRebase.hpp"
