// `geostatic` initial stress (2D and 3D; see Fields.hpp, docs/theory/plasticity.md §P10): a
// body at rest under its own weight with no lateral strain,
//   σ_v = −ρ0 |g| d,   σ_h = K0 σ_v (every horizontal direction, in 2D also zz),
// where d is the particle's depth below the body's top surface: the highest particle of the
// body in the same vertical column (columns one spacing wide), plus half a spacing (particles
// sit at the centres of their cells). "Vertical" is along the case's gravity.
//   K0 | σ_h/σ_v, > 0 | the material's own: 1 − sin φ (Jaky) for druckerPrager, ν/(1 − ν) for
//      |              | the other plastic materials
#include "core/Format.hpp"
#include "core/InputError.hpp"
#include "initialConditions/fields/Fields.hpp"

#include <algorithm>
#include <cmath>
#include <array>
#include <limits>
#include <map>

namespace sph
{

template <int D>
class GeostaticStress : public StressField<D>
{
public:
    static std::string description()
    {
        return "A body at rest under its own weight: vertical stress -rho g depth below the "
               "body's top, horizontal K0 times it (K0 default: the material's at-rest "
               "coefficient, 1 - sin(phi) for druckerPrager).";
    }
    static Schema schema()
    {
        return Schema().add(Key::real("K0", "horizontal over vertical stress (default: the "
                                            "material's at-rest coefficient)")
                                .positive()
                                .optional());
    }

    GeostaticStress(const Params& p, const typename StressField<D>::Args& args)
        : density_(args.density), X_(*args.X)
    {
        const double g = args.gravity.norm();
        if (!(g > 0.0))
        {
            p.fail("type", "geostatic: the stress of a body under its own weight needs gravity",
                   {"Add the acceleration of gravity at the top level of constant/bodies, e.g. "
                    "gravity (0 -9.81);"});
        }
        gravity_ = g;
        up_ = -args.gravity / g;
        atRest_ = p.has("K0") ? p.real("K0") : args.atRest;
        if (!std::isfinite(atRest_))
        {
            p.fail("type", "geostatic: the body's material has no at-rest coefficient K0",
                   {"Give it: K0 0.5; (horizontal over vertical stress)."});
        }
        // Columns one (mean) spacing wide, counted from the body's first horizontal
        // coordinate so that a lattice's particles sit in the middle of theirs.
        double spacing = 0.0;
        for (std::size_t a = args.begin; a < args.end; ++a)
        {
            spacing += std::pow((*args.V0)[a], 1.0 / D);
        }
        spacing_ = spacing / static_cast<double>(std::max<std::size_t>(1, args.end - args.begin));
        origin_ = Vec<D>::Constant(std::numeric_limits<double>::infinity());
        for (std::size_t a = args.begin; a < args.end; ++a)
        {
            origin_ = origin_.cwiseMin(horizontal(X_[a]));
        }
        for (std::size_t a = args.begin; a < args.end; ++a)
        {
            const auto key = column(X_[a]);
            const double height = X_[a].dot(up_) + 0.5 * spacing_;
            const auto found = top_.find(key);
            if (found == top_.end() || found->second < height)
            {
                top_[key] = height;
            }
        }
    }

    Eigen::Matrix3d stress(std::size_t a) const override
    {
        const double depth = top_.at(column(X_[a])) - X_[a].dot(up_);
        const double vertical = -density_ * gravity_ * depth;
        Eigen::Matrix3d up3 = Eigen::Matrix3d::Zero();
        up3.topLeftCorner<D, D>() = up_ * up_.transpose();
        return atRest_ * vertical * (Eigen::Matrix3d::Identity() - up3) + vertical * up3;
    }

private:
    Vec<D> horizontal(const Vec<D>& x) const { return x - x.dot(up_) * up_; }
    std::array<long, D> column(const Vec<D>& x) const
    {
        const Vec<D> h = horizontal(x) - origin_;
        std::array<long, D> key{};
        for (int d = 0; d < D; ++d)
        {
            key[static_cast<std::size_t>(d)] = std::lround(h[d] / spacing_);
        }
        return key;
    }

    double density_;
    const std::vector<Vec<D>>& X_;
    double gravity_ = 0.0;
    Vec<D> up_ = Vec<D>::Zero();
    double atRest_ = 0.0;
    double spacing_ = 0.0;
    Vec<D> origin_;
    std::map<std::array<long, D>, double> top_; // highest surface of each column
};

SPH_REGISTER_DIM_MODEL(StressField, GeostaticStress, "geostatic");

} // namespace sph
