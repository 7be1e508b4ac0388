// `annulus` (2D): a square lattice through the centre, clipped to
// innerRadius <= |x - centre| <= outerRadius. Mirror-symmetric about the centre, so two rings
// built the same way are exact mirror images.
// Keys:
//   centre      | centre [m]           | required
//   innerRadius | inner radius [m]     | required
//   outerRadius | outer radius [m]     | required
//   spacing     | particle spacing [m] | required
#include "initialConditions/generators/Generator.hpp"

namespace sph
{

template <int D>
class Annulus : public Generator<D>
{
public:
    static std::string description()
    {
        return "Annulus (2D): square lattice through the centre clipped to inner <= r <= "
               "outer radius (the seed's rubber rings).";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::vector("centre", "centre [m]"))
            .add(Key::real("innerRadius", "inner radius [m]").nonNegative())
            .add(Key::real("outerRadius", "outer radius [m]").positive())
            .add(Key::real("spacing", "particle spacing [m]").positive());
    }
    Annulus(const Params& p, const typename Generator<D>::Args&)
        : centre_(toVec<D>(p.vector("centre"))), inner_(p.real("innerRadius")),
          outer_(p.real("outerRadius")), spacing_(p.real("spacing"))
    {
        if (!(outer_ > inner_))
        {
            p.fail("outerRadius", "annulus: 'outerRadius' must exceed 'innerRadius'");
        }
        checkLatticeSize<D>(p, "annulus", Vec<D>::Constant(2.0 * outer_), spacing_);
    }
    GeneratedBody<D> generate() const override
    {
        return latticeInAnnulus<D>(centre_, inner_, outer_, spacing_);
    }

private:
    Vec<D> centre_;
    double inner_;
    double outer_;
    double spacing_;
};

SPH_REGISTER_DIM_MODEL_FOR(Generator, Annulus, "annulus", 2);

} // namespace sph
