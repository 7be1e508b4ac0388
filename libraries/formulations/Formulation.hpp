#pragma once
// Formulations decide when the reference configuration moves (spec §3, §4):
//
//   formulation { type totalLagrangian; }
//   formulation { type updatedLagrangian; referenceUpdateInterval 1; }
//   formulation { type updatedLagrangian; splitKick yes; }       // no energy from the moves' kicks
//   formulation { type updatedLagrangian; referenceUpdateStrain 0.01; } // moves by the motion
//   formulation { type totalLagrangian; kernelValues recomputed; }   // less memory, more time
//
// Total-Lagrangian keeps x^r = X for the whole run (kernel fixed in the initial configuration:
// no tensile instability, spec §3.2). Updated-Lagrangian moves x^r to the current positions
// every referenceUpdateInterval steps (x^r ← x, F^r ← F, V^r ← J V0, K carried for gradF),
// rebuilding neighbours, kernels and corrected gradients.

#include "core/Registry.hpp"

#include <string>

namespace sph
{

template <int D>
class Formulation : public RegisteredModel
{
public:
    static constexpr const char* family = "formulation";
    static constexpr int dimension = D;
    struct Args
    {
    };

    virtual ~Formulation() = default;

    // Whether the reference configuration ever moves.
    virtual bool updatesReference() const = 0;
    // Whether it moves at `step`, last moved at `lastUpdate`, the motion since then having
    // strained the particles by `strainSinceUpdate` at most (ReferenceManager::measureStrain()).
    virtual bool updateDue(long step, long lastUpdate, double strainSinceUpdate) const = 0;
    // Whether updateDue() reads the strain since the last move (the solver then measures it
    // at every level: ReferenceManager::measureStrain()).
    virtual bool movesByStrain() const { return false; }
    // Whether the kick at a level where the reference moves is split: the step that ends there
    // closes with the forces of its own reference, the next opens with the moved one's
    // (docs/theory/gradF-plastic.md §G20).
    virtual bool splitsKickAtMoves() const { return false; }

    // Whether the kernel values per pair (W and W'/r, 16 B per pair) are recomputed where they
    // are used instead of stored (particles/ReferenceConfiguration.hpp): the same results, bit
    // for bit, in less memory and more time.
    bool recomputesKernelValues() const { return recomputesKernelValues_; }

protected:
    // The key every formulation takes.
    static Key kernelValuesKey()
    {
        return Key::word("kernelValues",
                         "kernel values per neighbour pair: stored (fast) or recomputed where "
                         "they are used (16 B per pair less: about 1.2 kB per particle in 3D, "
                         "for 7-36 % more time per step with gradF and about twice the time "
                         "with none; the same results)")
            .choices({"stored", "recomputed"})
            .defaultValue("stored");
    }
    explicit Formulation(const Params& params)
        : recomputesKernelValues_(params.word("kernelValues") == "recomputed")
    {
    }

private:
    bool recomputesKernelValues_ = false;
};

} // namespace sph
