#pragma once
// Formulations decide when the reference configuration moves (spec §3, §4):
//
//   formulation { type totalLagrangian; }
//   formulation { type updatedLagrangian; referenceUpdateInterval 1; }
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
    // Whether it moves at `step`, last moved at `lastUpdate`.
    virtual bool updateDue(long step, long lastUpdate) const = 0;
};

} // namespace sph
