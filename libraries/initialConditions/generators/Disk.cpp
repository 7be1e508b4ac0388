// `disk` (2D): a square lattice through the centre clipped to |x - centre| <= radius.
// Keys:
//   centre  | centre [m]           | required
//   radius  | radius [m]           | required
//   spacing | particle spacing [m] | required
#include "initialConditions/generators/Generator.hpp"

namespace sph
{

template <int D>
class Disk : public Generator<D>
{
public:
    static std::string description()
    {
        return "Disk (2D): square lattice through the centre clipped to r <= radius.";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::vector("centre", "centre [m]"))
            .add(Key::real("radius", "radius [m]").positive())
            .add(Key::real("spacing", "particle spacing [m]").positive());
    }
    Disk(const Params& p, const typename Generator<D>::Args&)
        : centre_(toVec<D>(p.vector("centre"))), radius_(p.real("radius")),
          spacing_(p.real("spacing"))
    {
        checkLatticeSize<D>(p, "disk", Vec<D>::Constant(2.0 * radius_), spacing_);
    }
    GeneratedBody<D> generate() const override
    {
        return latticeInAnnulus<D>(centre_, -1.0, radius_, spacing_);
    }

private:
    Vec<D> centre_;
    double radius_;
    double spacing_;
};

SPH_REGISTER_DIM_MODEL_FOR(Generator, Disk, "disk", 2);

} // namespace sph
