#pragma once
// What the profile objects (surfaceProfile, failureLine) share: the bodies they read, the
// width of their columns along x and half a particle spacing (the cell a particle centre
// stands for: a surface is a centre plus half a spacing, a failure height a centre minus it).
// The spacing is V0^(1/D) (a 3D surfaceProfile profiles a slice of a slab).
// Keys:
//   bodies     | which bodies ( ) = all                                         | ()
//   binWidth   | column width [m], > 0                                          | the spacing

#include "functionObjects/FunctionObject.hpp"

#include <cmath>
#include <vector>

namespace sph
{

struct ProfileColumns
{
    std::vector<std::size_t> bodies; // body indices, all when the key lists none
    double half = 0.0;               // half the mean spacing V0^(1/D) of their particles
    double width = 0.0;              // column width

    static Schema addKeys(Schema schema)
    {
        return schema.add(Key::bodyList("bodies", "which bodies; () = all").distinct().defaultValue("()"))
            .add(Key::real("binWidth", "column width [m] (default: the particle spacing)")
                     .positive()
                     .optional());
    }

    template <int D>
    static ProfileColumns read(const Params& params, const typename FunctionObject<D>::Args& args)
    {
        ProfileColumns columns;
        columns.bodies = params.bodyIndices("bodies");
        if (columns.bodies.empty())
        {
            for (std::size_t b = 0; b < args.bodyNames->size(); ++b)
            {
                columns.bodies.push_back(b);
            }
        }
        const ParticleSet<D>& p = *args.initial;
        double spacing = 0.0;
        std::size_t count = 0;
        for (const std::size_t b : columns.bodies)
        {
            for (std::size_t a = p.bodies[b].begin; a < p.bodies[b].end; ++a)
            {
                spacing += D == 3 ? std::cbrt(p.V0[a]) : std::sqrt(p.V0[a]);
                ++count;
            }
        }
        columns.half = count > 0 ? 0.5 * spacing / static_cast<double>(count) : 0.0;
        columns.width = params.has("binWidth") ? params.real("binWidth") : 2.0 * columns.half;
        return columns;
    }
};

} // namespace sph
