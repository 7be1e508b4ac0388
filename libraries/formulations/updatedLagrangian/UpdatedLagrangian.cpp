// `updatedLagrangian`: CSPH with a moving reference configuration (Vidal, Bonet & Huerta 2007;
// seed §2.3; spec §4).
// Keys:
//   referenceUpdateInterval | steps between moves of the reference configuration | 1
//                | (with referenceUpdateStrain: the most steps, if given)     | (none)
//   referenceUpdateStrain | > 0: move when the largest strain of the motion since  | none
//                | the last move, max_a |½(f_aᵀ f_a − I)|, f_a = F_a F^r_a⁻¹, |
//                | reaches it (a schedule in motion, not in steps: the same   |
//                | discretisation at every step size, gradF-plastic.md §G21)  |
//   kernelValues | stored | recomputed: W and W'/r per pair kept or recomputed | stored
//   splitKick    | yes: at a move the step that ends closes with the forces of | no
//                | the reference it began with, the next opens with the moved  |
//                | one's (one more force evaluation per move; the moves' kicks |
//                | then add no energy: docs/theory/gradF-plastic.md §G20)      |
// Every step (1, the default) is the most unstable setting and the one in which the seed's
// Dyka bar instability shows (spec §4).
#include "formulations/Formulation.hpp"

#include <limits>
#include <optional>

namespace sph
{

template <int D>
class UpdatedLagrangian : public Formulation<D>
{
public:
    static std::string description()
    {
        return "Updated-Lagrangian CSPH: the reference configuration moves to the current one "
               "every referenceUpdateInterval steps, or when the strain since the last move "
               "reaches referenceUpdateStrain (spec §4).";
    }
    static Schema schema()
    {
        return Schema().add(Key::integer("referenceUpdateInterval",
                                         "time steps between moves of the reference "
                                         "configuration (with referenceUpdateStrain: the most "
                                         "steps between moves, unlimited if not given)")
                                .min(1)
                                .defaultValue("1"))
            .add(Key::real("referenceUpdateStrain",
                           "move the reference when the largest strain of the motion since the "
                           "last move, max |(f^T f - I)/2| over the particles (Frobenius norm, "
                           "f = F F^r^-1), "
                           "reaches this: moves follow the motion, not the step count "
                           "(docs/theory/gradF-plastic.md §G21)")
                     .range(0.0, 1.0, false, true)
                     .optional())
            .add(Key::boolean("splitKick",
                              "at a level where the reference moves, close the step that ends "
                              "there with the forces of the reference it began with and open "
                              "the next with the moved one's: every step is then the leapfrog "
                              "of one energy, and moves that keep the energy (gradF moveWeights "
                              "conserving) make none through the kicks either; one more force "
                              "evaluation per move (docs/theory/gradF-plastic.md §G20)")
                     .defaultValue("no"))
            .add(Formulation<D>::kernelValuesKey());
    }
    UpdatedLagrangian(const Params& params, const typename Formulation<D>::Args&)
        : Formulation<D>(params), interval_(params.integer("referenceUpdateInterval")),
          splitKick_(params.boolean("splitKick"))
    {
        if (params.has("referenceUpdateStrain"))
        {
            strain_ = params.real("referenceUpdateStrain");
            if (!params.given("referenceUpdateInterval"))
            {
                interval_ = std::numeric_limits<long>::max();
            }
        }
    }

    bool updatesReference() const override { return true; }
    bool updateDue(long step, long lastUpdate, double strainSinceUpdate) const override
    {
        if (step == lastUpdate)
        {
            return false;
        }
        return step - lastUpdate >= interval_ || (strain_ && strainSinceUpdate >= *strain_);
    }
    bool movesByStrain() const override { return strain_.has_value(); }
    bool splitsKickAtMoves() const override { return splitKick_; }

private:
    long interval_;
    bool splitKick_;
    std::optional<double> strain_; // referenceUpdateStrain
};

SPH_REGISTER_DIM_MODEL(Formulation, UpdatedLagrangian, "updatedLagrangian");

} // namespace sph
