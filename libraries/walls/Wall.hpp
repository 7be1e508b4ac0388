#pragma once
// Rigid walls (constant/walls, an optional file): one entry per wall,
//
//   floor   { type plane; point (0 0); normal (0 1); friction 0.3; bodies (bar); removeAt 0.5; }
//   footing { type box; min (-0.05 0.2); max (0.05 0.3); velocity (0 -1e-3); friction 1; }
//
// The types (sphSolid -listTypes wall prints their keys):
//   plane | an infinite plane (a line in 2D, a point in 1D), the solid on its normal's side
//         | (walls/plane/PlaneWall.cpp)
//   box   | a finite axis-aligned box [min, max] (a rectangle in 2D, an interval in 1D), the
//         | solid outside it: a footing or a punch (walls/box/BoxWall.cpp)
// A wall type defines only its shape at t = 0, as the signed distance of a point along the
// outward normal; what every wall has — friction, a prescribed translation, the bodies it acts
// on, the time it is removed — is read here, and the contact law that turns distances into
// forces is one for all types (walls/WallSet.hpp).
//
// Keys common to every wall:
//   friction | Coulomb coefficient μ >= 0                                  | 0
//   velocity | prescribed translation [m/s]: the wall at t is its shape at | 0
//            | t = 0 moved by velocity t                                   |
//   bodies   | the bodies it acts on; () = every body                      | ()
//   removeAt | the wall stops acting at this time [s] (a gate)             | never

#include "core/Registry.hpp"
#include "particles/Types.hpp"

#include <limits>
#include <string>
#include <vector>

namespace sph
{

template <int D>
class Wall : public RegisteredModel
{
public:
    static constexpr const char* family = "wall";
    static constexpr int dimension = D;
    struct Args
    {
        std::vector<std::string> bodyNames; // in body-index order
    };

    // Where a point is relative to the wall: its signed distance along the outward normal
    // (positive on the solid's side) and that unit normal.
    struct Side
    {
        double distance = 0.0;
        Vec<D> normal = Vec<D>::Zero();
    };

    virtual ~Wall() = default;

    // The wall at time t is its shape at t = 0 translated by velocity t.
    Side side(const Vec<D>& x, double t) const { return sideAtStart(x - velocity_ * t); }
    const Vec<D>& velocity() const { return velocity_; }
    bool moves() const { return !velocity_.isZero(); }
    double friction() const { return friction_; }
    // The gate: the wall acts while t < removeAt.
    bool presentAt(double t) const { return t < removeAt_; }
    bool actsOn(std::size_t body) const { return actsOn_[body] != 0; }

    static Schema commonSchema()
    {
        return Schema()
            .add(Key::real("friction", "Coulomb friction coefficient mu").nonNegative().defaultValue("0"))
            .add(Key::vector("velocity", "prescribed wall velocity [m/s]: the wall at time t is its "
                                         "shape at t = 0 moved by velocity t")
                     .defaultValue("0"))
            .add(Key::bodyList("bodies", "the bodies the wall acts on; () = every body")
                     .distinct()
                     .defaultValue("()"))
            .add(Key::real("removeAt", "time at which the wall stops acting [s] (absent: never)")
                     .nonNegative()
                     .optional());
    }

protected:
    Wall(const Params& params, const Args& args)
        : velocity_(toVec<D>(params.vector("velocity"))), friction_(params.real("friction")),
          removeAt_(params.has("removeAt") ? params.real("removeAt")
                                           : std::numeric_limits<double>::infinity())
    {
        const std::vector<std::size_t> chosen = params.bodyIndices("bodies");
        actsOn_.assign(args.bodyNames.size(), chosen.empty() ? 1 : 0);
        for (const std::size_t body : chosen)
        {
            actsOn_[body] = 1;
        }
    }

    // The shape at t = 0: the side of x (see Side).
    virtual Side sideAtStart(const Vec<D>& x) const = 0;

private:
    Vec<D> velocity_;
    double friction_;
    double removeAt_;
    std::vector<std::uint8_t> actsOn_; // by body index
};

} // namespace sph
