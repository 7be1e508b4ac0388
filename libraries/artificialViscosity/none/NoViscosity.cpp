// `none`: no artificial viscosity; no search, no cost. Keys: none.
#include "artificialViscosity/ArtificialViscosity.hpp"

namespace sph
{

template <int D>
class NoViscosity : public ArtificialViscosity<D>
{
public:
    static std::string description() { return "No artificial viscosity (no search, no cost)."; }
    static Schema schema() { return Schema(); }
    NoViscosity(const Params&, const typename ArtificialViscosity<D>::Args&) {}

    bool active() const override { return false; }
    void compute(const ViscosityState<D>&, std::vector<Vec<D>>&) override {}
};

SPH_REGISTER_DIM_MODEL(ArtificialViscosity, NoViscosity, "none");

} // namespace sph
