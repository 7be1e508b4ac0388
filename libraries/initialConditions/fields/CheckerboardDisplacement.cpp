// `checkerboard` initial displacement field (x = X + u at t = 0; see Fields.hpp): the
// zero-energy pattern.
//   amplitude, spacing, direction, origin
//   u = amplitude (-1)^(Σ_d round((X_d - o_d)/spacing)) · direction/|direction|
#include "initialConditions/fields/Fields.hpp"

#include <cmath>

namespace sph
{

template <int D>
class CheckerboardDisplacement : public DisplacementField<D>
{
public:
    static std::string description()
    {
        return "Alternating +/- displacement from lattice site to lattice site (the hourglass / "
               "zero-energy pattern).";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::real("amplitude", "displacement [m]"))
            .add(Key::real("spacing", "the lattice spacing [m]").positive())
            .add(Key::vector("direction", "direction of the displacement"))
            .add(Key::vector("origin", "a lattice site [m]").defaultValue("0"));
    }
    CheckerboardDisplacement(const Params& p, const typename DisplacementField<D>::Args&)
        : amplitude_(p.real("amplitude")), spacing_(p.real("spacing")),
          direction_(toVec<D>(p.vector("direction"))), origin_(toVec<D>(p.vector("origin")))
    {
        if (direction_.norm() == 0.0)
        {
            p.fail("direction", "checkerboard: 'direction' must not be zero");
        }
        direction_.normalize();
    }
    Vec<D> displacement(const Vec<D>& X, std::size_t) const override
    {
        long sum = 0;
        for (int d = 0; d < D; ++d)
        {
            sum += std::lround((X[d] - origin_[d]) / spacing_);
        }
        return (sum % 2 == 0 ? amplitude_ : -amplitude_) * direction_;
    }

private:
    double amplitude_;
    double spacing_;
    Vec<D> direction_;
    Vec<D> origin_;
};

SPH_REGISTER_DIM_MODEL(DisplacementField, CheckerboardDisplacement, "checkerboard");

} // namespace sph
