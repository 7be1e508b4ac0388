// `polygon` (2D): the cell-centred lattice of the polygon's bounding box (as `box` makes it:
// centres at lower + spacing (i + 1/2, j + 1/2)) clipped to the polygon: a slope, an embankment,
// a wedge. A rectangle gives exactly `box`'s particles. Every particle has the volume
// spacing², so the volumes tile the polygon up to the cells its slanted edges cut (the total
// volume, in sphParticles' log, is the polygon's area to within about half a cell per spacing
// of slanted edge).
// A centre on an edge is inside on the edge's left or bottom side only (half-open cells), so
// two polygons that share an edge share no particle and leave none out.
// Keys:
//   vertices | the corners in order, either way round, at least 3 [m]; a simple polygon
//            | (no edge crosses another, no two corners equal)             | required
//   spacing  | particle spacing [m]                                       | required
#include "core/Format.hpp"
#include "initialConditions/generators/Generator.hpp"

#include <algorithm>

namespace sph
{

namespace
{

double cross(const Vec<2>& a, const Vec<2>& b)
{
    return a[0] * b[1] - a[1] * b[0];
}

// Whether the closed segments [a, b] and [c, d] meet (collinear overlaps included).
bool segmentsMeet(const Vec<2>& a, const Vec<2>& b, const Vec<2>& c, const Vec<2>& d)
{
    const double d1 = cross(b - a, c - a);
    const double d2 = cross(b - a, d - a);
    const double d3 = cross(d - c, a - c);
    const double d4 = cross(d - c, b - c);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    {
        return true;
    }
    const auto onSegment = [](const Vec<2>& p, const Vec<2>& q, const Vec<2>& r)
    {
        return std::min(p[0], q[0]) <= r[0] && r[0] <= std::max(p[0], q[0]) &&
               std::min(p[1], q[1]) <= r[1] && r[1] <= std::max(p[1], q[1]);
    };
    return (d1 == 0 && onSegment(a, b, c)) || (d2 == 0 && onSegment(a, b, d)) ||
           (d3 == 0 && onSegment(c, d, a)) || (d4 == 0 && onSegment(c, d, b));
}

} // namespace

template <int D> class Polygon : public Generator<D>
{
public:
    static std::string description()
    {
        return "Polygon (2D): the cell-centred lattice of its bounding box clipped to a simple "
               "polygon given by its vertices (a slope, an embankment).";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::vectorList("vertices", "the polygon's corners in order [m], at least 3"))
            .add(Key::real("spacing", "particle spacing [m]").positive());
    }
    Polygon(const Params& p, const typename Generator<D>::Args&) : spacing_(p.real("spacing"))
    {
        for (const auto& v : p.vectorList("vertices"))
        {
            vertices_.push_back(toVec<D>(v));
        }
        const std::size_t n = vertices_.size();
        if (n < 3)
        {
            p.fail("vertices", "polygon: " + std::to_string(n) + " vertices do not enclose an area",
                   {"Give at least 3 corners in order, e.g. vertices ((0 0) (3 0) (0 1));"});
        }
        double area = 0.0;
        for (std::size_t i = 0; i < n; ++i)
        {
            area += cross(vertices_[i], vertices_[(i + 1) % n]);
        }
        area_ = std::abs(area) / 2.0;
        for (std::size_t i = 0; i < n; ++i)
        {
            for (std::size_t j = i + 1; j < n; ++j)
            {
                if (vertices_[i] == vertices_[j])
                {
                    p.fail("vertices", j,
                           "polygon: corners " + std::to_string(i + 1) + " and " +
                               std::to_string(j + 1) + " are the same point",
                           {"List each corner once; the polygon closes itself."});
                }
            }
        }
        for (std::size_t i = 0; i < n; ++i)
        {
            for (std::size_t j = i + 1; j < n; ++j)
            {
                const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
                if (!adjacent && segmentsMeet(vertices_[i], vertices_[(i + 1) % n], vertices_[j],
                                              vertices_[(j + 1) % n]))
                {
                    p.fail("vertices", i,
                           "polygon: its edge from corner " + std::to_string(i + 1) +
                               " meets the edge from corner " + std::to_string(j + 1) +
                               ": it is not a simple polygon",
                           {"List the corners in order round the boundary (either way), with no "
                            "edge crossing another."});
                }
            }
        }
        if (!(area_ > 0.0))
        {
            p.fail("vertices", "polygon: the corners are collinear (zero area)",
                   {"List the corners of a polygon with an area."});
        }
        lower_ = upper_ = vertices_.front();
        for (const Vec<D>& v : vertices_)
        {
            lower_ = lower_.cwiseMin(v);
            upper_ = upper_.cwiseMax(v);
        }
        checkLatticeSize<D>(p, "polygon", upper_ - lower_, spacing_);
        if (generate().X.empty())
        {
            p.fail("spacing",
                   "polygon: no particle centre falls inside the polygon at spacing " +
                       formatNumber(spacing_) + " m",
                   {"Choose a spacing well below the polygon's narrowest width."});
        }
    }
    GeneratedBody<D> generate() const override
    {
        const Vec<D> origin = lower_ + Vec<D>::Constant(0.5 * spacing_);
        return clippedLattice<D>(origin, spacing_, lower_, upper_,
                                 [this](const Vec<D>& x) { return inside(x); });
    }

private:
    // Even-odd crossing count with half-open rules (an edge counts when y lies in [y0, y1) of
    // it, and a point counts as left of the crossing when x < the edge's x there): a centre on
    // a left or bottom edge is inside, on a right or top edge outside.
    bool inside(const Vec<D>& x) const
    {
        bool in = false;
        const std::size_t n = vertices_.size();
        for (std::size_t i = 0, j = n - 1; i < n; j = i++)
        {
            // The edge from its lower end, so that two polygons sharing it compute the same
            // crossing to the last digit.
            const bool upward = vertices_[i][1] < vertices_[j][1];
            const Vec<D>& a = upward ? vertices_[i] : vertices_[j];
            const Vec<D>& b = upward ? vertices_[j] : vertices_[i];
            if ((a[1] <= x[1]) != (b[1] <= x[1]))
            {
                const double at = a[0] + (x[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
                if (x[0] < at)
                {
                    in = !in;
                }
            }
        }
        return in;
    }

    std::vector<Vec<D>> vertices_;
    Vec<D> lower_;
    Vec<D> upper_;
    double spacing_;
    double area_ = 0.0;
};

SPH_REGISTER_DIM_MODEL_FOR(Generator, Polygon, "polygon", 2);

} // namespace sph
