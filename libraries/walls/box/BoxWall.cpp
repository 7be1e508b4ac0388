// `box`: a finite rigid body, the axis-aligned box [min, max] (a rectangle in 2D, an interval
// in 1D), with the solid OUTSIDE it: a footing, a punch, an indenter. At t = 0 a point x is at
// the signed distance
//   outside: d = |x - c| > 0,  n̂ = (x - c)/|x - c|,  c = the point of the box nearest to x
//            (x clamped to [min, max]: a face's normal off a face, from the edge or corner
//            point off an edge or a corner, so a particle there is pushed away from that point);
//   inside:  d = -(depth below the nearest face) <= 0,  n̂ = that face's outward normal;
// at t the box is moved by velocity t (walls/WallSet.hpp turns d into the contact force).
// d is the Euclidean distance, continuous everywhere, and n̂ = ∇d wherever d is differentiable
// (everywhere but where two faces are equally near inside), so the force k δ n̂ of WallSet is
// -∇(½ k δ²) and the contact stays conservative round the corners.
// Keys:
//   min | lower corner at t = 0 [m]                     | required
//   max | upper corner at t = 0 [m], above min in every | required
//       | component                                     |
//   and the keys of every wall (walls/Wall.hpp).
#include "core/Format.hpp"
#include "walls/Wall.hpp"

namespace sph
{

template <int D>
class BoxWall : public Wall<D>
{
public:
    static std::string description()
    {
        return "Rigid axis-aligned box [min, max] (a rectangle in 2D, an interval in 1D), the "
               "solid outside it: a footing or punch, pushed at a prescribed velocity; the same "
               "penalty contact, friction and removal time as a plane.";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::vector("min", "lower corner at t = 0 [m]"))
            .add(Key::vector("max", "upper corner at t = 0 [m], above min in every component"))
            .include(Wall<D>::commonSchema());
    }

    BoxWall(const Params& params, const typename Wall<D>::Args& args)
        : Wall<D>(params, args), min_(toVec<D>(params.vector("min"))),
          max_(toVec<D>(params.vector("max")))
    {
        for (int d = 0; d < D; ++d)
        {
            if (!(max_[d] > min_[d]))
            {
                const std::string axis(1, "xyz"[d]);
                params.fail("max", static_cast<std::size_t>(d),
                            "box: max " + axis + " = " + formatNumber(max_[d]) +
                                " must lie in (" + formatNumber(min_[d]) + ", inf), above min " +
                                axis + " = " + formatNumber(min_[d]),
                            {"'min' is the lower corner of the box and 'max' the upper one, e.g. "
                             "footing { type box; min (-0.05 0.2); max (0.05 0.3); }; the solid "
                             "stays outside the box."});
            }
        }
    }

private:
    typename Wall<D>::Side sideAtStart(const Vec<D>& x) const override
    {
        const Vec<D> gap = x - x.cwiseMax(min_).cwiseMin(max_);
        const double distance = gap.norm();
        if (distance > 0.0)
        {
            return {distance, gap / distance};
        }
        Eigen::Index lowerAxis = 0;
        Eigen::Index upperAxis = 0;
        const double lower = (x - min_).minCoeff(&lowerAxis);
        const double upper = (max_ - x).minCoeff(&upperAxis);
        const bool lowerNearer = lower <= upper;
        Vec<D> normal = Vec<D>::Zero();
        normal[lowerNearer ? lowerAxis : upperAxis] = lowerNearer ? -1.0 : 1.0;
        return {-std::min(lower, upper), normal};
    }

    Vec<D> min_;
    Vec<D> max_;
};

SPH_REGISTER_DIM_MODEL(Wall, BoxWall, "box");

} // namespace sph
