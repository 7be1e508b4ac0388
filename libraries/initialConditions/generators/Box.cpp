// `box` (1D/2D/3D): a lattice filling [min, max] with cell-centred particles, so the volumes
// tile the box exactly; the extent must be a whole number of spacings in every direction.
// Keys:
//   min     | lower corner [m]     | required
//   max     | upper corner [m]     | required
//   spacing | particle spacing [m] | required
#include "core/Format.hpp"
#include "initialConditions/generators/Generator.hpp"

#include <cmath>

namespace sph
{

template <int D> class Box : public Generator<D>
{
public:
    static std::string description()
    {
        return "Box [min, max] filled with a cell-centred lattice (volumes tile the box).";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::vector("min", "lower corner [m]"))
            .add(Key::vector("max", "upper corner [m]"))
            .add(Key::real("spacing", "particle spacing [m]").positive());
    }
    Box(const Params& p, const typename Generator<D>::Args&)
        : min_(toVec<D>(p.vector("min"))), max_(toVec<D>(p.vector("max"))),
          spacing_(p.real("spacing"))
    {
        if (!(max_.array() > min_.array()).all())
        {
            p.fail("max", "box: 'max' must be greater than 'min' in every component",
                   {"min is the lower corner, max the upper one."});
        }
        checkLatticeSize<D>(p, "box", max_ - min_, spacing_);
        for (int d = 0; d < D; ++d)
        {
            const double cells = (max_[d] - min_[d]) / spacing_;
            if (std::abs(cells - std::round(cells)) > 1e-6 * cells)
            {
                p.fail("spacing",
                       "box: the extent " + formatNumber(max_[d] - min_[d]) + " m along " +
                           "xyz"[d] + " is not a whole number of spacings (" + formatNumber(cells) +
                           ")",
                       {"Choose max - min as a multiple of 'spacing' (particles sit at cell "
                        "centres so that their volumes tile the box)."});
            }
        }
    }
    GeneratedBody<D> generate() const override
    {
        const Vec<D> origin = min_ + Vec<D>::Constant(0.5 * spacing_);
        const Vec<D> lower = min_;
        const Vec<D> upper = max_;
        return clippedLattice<D>(origin, spacing_, lower, upper,
                                 [&](const Vec<D>& x) {
                                     return (x.array() > lower.array()).all() &&
                                            (x.array() < upper.array()).all();
                                 });
    }

private:
    Vec<D> min_;
    Vec<D> max_;
    double spacing_;
};

SPH_REGISTER_DIM_MODEL(Generator, Box, "box");

} // namespace sph
