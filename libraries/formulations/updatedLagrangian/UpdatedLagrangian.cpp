// `updatedLagrangian`: CSPH with a moving reference configuration (Vidal, Bonet & Huerta 2007;
// seed §2.3; spec §4).
// Keys:
//   referenceUpdateInterval | steps between moves of the reference configuration | 1
//   kernelValues | stored | recomputed: W and W'/r per pair kept or recomputed | stored
//   splitKick    | yes: at a move the step that ends closes with the forces of | no
//                | the reference it began with, the next opens with the moved  |
//                | one's (one more force evaluation per move; the moves' kicks |
//                | then add no energy: docs/theory/gradF-plastic.md §G20)      |
// Every step (1, the default) is the most unstable setting and the one in which the seed's
// Dyka bar instability shows (spec §4).
#include "formulations/Formulation.hpp"

namespace sph
{

template <int D>
class UpdatedLagrangian : public Formulation<D>
{
public:
    static std::string description()
    {
        return "Updated-Lagrangian CSPH: the reference configuration moves to the current one "
               "every referenceUpdateInterval steps (spec §4).";
    }
    static Schema schema()
    {
        return Schema().add(Key::integer("referenceUpdateInterval",
                                         "time steps between moves of the reference "
                                         "configuration")
                                .min(1)
                                .defaultValue("1"))
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
    }

    bool updatesReference() const override { return true; }
    bool updateDue(long step, long lastUpdate) const override
    {
        return step - lastUpdate >= interval_;
    }
    bool splitsKickAtMoves() const override { return splitKick_; }

private:
    long interval_;
    bool splitKick_;
};

SPH_REGISTER_DIM_MODEL(Formulation, UpdatedLagrangian, "updatedLagrangian");

} // namespace sph
