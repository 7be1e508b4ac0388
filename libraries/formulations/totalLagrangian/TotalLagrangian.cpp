// `totalLagrangian`: CSPH in the initial configuration (Bonet & Kulasegaram 2000; spec §3).
// x^r = X, F^r = I for the whole run; neighbours, kernels and corrected gradients are built
// once. Keys:
//   kernelValues | stored | recomputed: W and W'/r per pair kept or recomputed | stored
#include "formulations/Formulation.hpp"

namespace sph
{

template <int D>
class TotalLagrangian : public Formulation<D>
{
public:
    static std::string description()
    {
        return "Total-Lagrangian CSPH: kernels and neighbours fixed in the initial "
               "configuration, never updated (spec §3).";
    }
    static Schema schema() { return Schema().add(Formulation<D>::kernelValuesKey()); }
    TotalLagrangian(const Params& params, const typename Formulation<D>::Args&)
        : Formulation<D>(params)
    {
    }

    bool updatesReference() const override { return false; }
    bool updateDue(long, long, double) const override { return false; }
};

SPH_REGISTER_DIM_MODEL(Formulation, TotalLagrangian, "totalLagrangian");

} // namespace sph
