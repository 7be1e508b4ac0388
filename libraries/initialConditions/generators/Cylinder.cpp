// `cylinder` (3D): a cubic lattice through the base centre clipped to the cylinder
// {0 <= (x - base)·axis <= length, distance from the axis <= radius}.
// Keys:
//   base    | centre of the base disk [m]        | required
//   axis    | direction of the axis (normalised)  | required
//   length  | length along the axis [m]           | required
//   radius  | radius [m]                          | required
//   spacing | particle spacing [m]                | required
#include "initialConditions/generators/Generator.hpp"

namespace sph
{

template <int D>
class Cylinder : public Generator<D>
{
public:
    static std::string description()
    {
        return "Cylinder (3D): cubic lattice through the base centre clipped to the cylinder.";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::vector("base", "centre of the base disk [m]"))
            .add(Key::vector("axis", "direction of the axis"))
            .add(Key::real("length", "length along the axis [m]").positive())
            .add(Key::real("radius", "radius [m]").positive())
            .add(Key::real("spacing", "particle spacing [m]").positive());
    }
    Cylinder(const Params& p, const typename Generator<D>::Args&)
        : base_(toVec<D>(p.vector("base"))), axis_(toVec<D>(p.vector("axis"))),
          length_(p.real("length")), radius_(p.real("radius")), spacing_(p.real("spacing"))
    {
        if (axis_.norm() == 0.0)
        {
            p.fail("axis", "cylinder: 'axis' must not be the zero vector");
        }
        axis_.normalize();
        checkLatticeSize<D>(p, "cylinder", Vec<D>::Constant(2.0 * (length_ + radius_)), spacing_);
    }
    GeneratedBody<D> generate() const override
    {
        const double tolerance = 1e-9 * spacing_;
        const double reach = length_ + radius_;
        return clippedLattice<D>(base_, spacing_, base_ - Vec<D>::Constant(reach),
                                 base_ + Vec<D>::Constant(reach), [&](const Vec<D>& x) {
                                     const Vec<D> r = x - base_;
                                     const double along = r.dot(axis_);
                                     const double across = (r - along * axis_).norm();
                                     return along >= -tolerance && along <= length_ + tolerance &&
                                            across <= radius_ + tolerance;
                                 });
    }

private:
    Vec<D> base_;
    Vec<D> axis_;
    double length_;
    double radius_;
    double spacing_;
};

SPH_REGISTER_DIM_MODEL_FOR(Generator, Cylinder, "cylinder", 3);

} // namespace sph
