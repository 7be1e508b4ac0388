// `plane`: an infinite plane (a line in 2D, a point in 1D) through `point` with outward normal
// `normal`; the solid is on the side the normal points to. A point x is at the signed distance
//   d(x, t) = (x - p(t))·n̂,   p(t) = point + velocity t,   n̂ = normal / |normal|,
// from the wall (walls/WallSet.hpp turns d into the contact force).
// Keys:
//   point  | a point of the plane at t = 0 [m]                          | required
//   normal | outward normal, from the wall into the solid's side; need | required
//          | not be unit, must not be zero                             |
//   and the keys of every wall (walls/Wall.hpp).
#include "walls/Wall.hpp"

namespace sph
{

template <int D>
class PlaneWall : public Wall<D>
{
public:
    static std::string description()
    {
        return "Rigid plane (a line in 2D, a point in 1D) through 'point' with outward normal "
               "'normal': a penalty wall as stiff as the material, with Coulomb friction, a "
               "prescribed velocity and a removal time.";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::vector("point", "a point of the plane at t = 0 [m]"))
            .add(Key::vector("normal", "outward normal, from the wall into the solid's side; need "
                                       "not be unit, must not be zero"))
            .include(Wall<D>::commonSchema());
    }

    PlaneWall(const Params& params, const typename Wall<D>::Args& args)
        : Wall<D>(params, args), point_(toVec<D>(params.vector("point")))
    {
        const Vec<D> normal = toVec<D>(params.vector("normal"));
        const double length = normal.norm();
        if (!(length > 0.0))
        {
            params.fail("normal", "plane: 'normal' must not be the zero vector (its length must be "
                                  "> 0)",
                        {"The normal points from the wall into the solid's side, e.g. normal (0 "
                         "1); for a floor under the solid."});
        }
        normal_ = normal / length;
    }

private:
    typename Wall<D>::Side sideAtStart(const Vec<D>& x) const override
    {
        return {(x - point_).dot(normal_), normal_};
    }

    Vec<D> point_;
    Vec<D> normal_ = Vec<D>::Zero();
};

SPH_REGISTER_DIM_MODEL(Wall, PlaneWall, "plane");

} // namespace sph
