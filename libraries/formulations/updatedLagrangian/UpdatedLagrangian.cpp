// `updatedLagrangian`: CSPH with a moving reference configuration (Vidal, Bonet & Huerta 2007;
// seed §2.3; spec §4).
// Keys:
//   referenceUpdateInterval | steps between moves of the reference configuration | 1
//   kernelValues | stored | recomputed: W and W'/r per pair kept or recomputed | stored
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
            .add(Formulation<D>::kernelValuesKey());
    }
    UpdatedLagrangian(const Params& params, const typename Formulation<D>::Args&)
        : Formulation<D>(params), interval_(params.integer("referenceUpdateInterval"))
    {
    }

    bool updatesReference() const override { return true; }
    bool updateDue(long step, long lastUpdate) const override
    {
        return step - lastUpdate >= interval_;
    }

private:
    long interval_;
};

SPH_REGISTER_DIM_MODEL(Formulation, UpdatedLagrangian, "updatedLagrangian");

} // namespace sph
