// `probes`: fields at the particles nearest to given points (nearest by initial position, so
// a probe follows its material point).
// Keys:
//   points | where to probe, by initial position [m]                            | required
//   fields | any of: position displacement velocity F P J                       | (displacement velocity)
//   body   | only look in this body                                             | optional
// Columns: <field>_<component> (x y z; xx xy ..), with _<i> appended when there are several
// points, e.g. displacement_x or displacement_x_1.
#include "core/Format.hpp"
#include "functionObjects/FunctionObjectModel.hpp"

#include <cmath>

namespace sph
{

template <int D>
class Probes : public FunctionObjectModel<D>
{
public:
    static std::string description()
    {
        return "Fields at the particles nearest to given points (by initial position).";
    }
    static Schema schema()
    {
        return FunctionObjectModel<D>::commonSchema()
            .add(Key::vectorList("points", "probe locations, by initial position [m]"))
            .add(Key::wordList("fields", "any of: position displacement velocity F P J")
                     .distinct()
                     .defaultValue("(displacement velocity)"))
            .add(Key::body("body", "only look in this body").optional());
    }

    Probes(const Params& params, const typename FunctionObject<D>::Args& args)
        : FunctionObjectModel<D>(params, args), fields_(params.wordList("fields"))
    {
        static const std::vector<std::string> known{"position", "displacement", "velocity",
                                                    "F",        "P",            "J"};
        for (std::size_t i = 0; i < fields_.size(); ++i)
        {
            if (std::find(known.begin(), known.end(), fields_[i]) == known.end())
            {
                params.fail("fields", i, "probes: unknown field '" + fields_[i] + "'",
                            {"Valid fields: " + joinSorted(known), didYouMean(fields_[i], known)});
            }
        }
        const ParticleSet<D>& particles = *args.initial;
        std::size_t begin = 0;
        std::size_t end = particles.size();
        if (params.has("body"))
        {
            const BodyRange& range = particles.bodies[params.bodyIndex("body")];
            begin = range.begin;
            end = range.end;
        }
        const auto& points = params.vectorList("points");
        for (std::size_t i = 0; i < points.size(); ++i)
        {
            const Vec<D> target = toVec<D>(points[i]);
            std::size_t best = begin;
            for (std::size_t a = begin; a < end; ++a)
            {
                if ((particles.X[a] - target).squaredNorm() < (particles.X[best] - target).squaredNorm())
                {
                    best = a;
                }
            }
            checkNear(params, i, particles, best, target, begin, end);
            particles_.push_back(best);
        }
        if (particles_.empty())
        {
            params.fail("points", "probes: give at least one point");
        }
        std::vector<std::string> columns;
        for (std::size_t i = 0; i < particles_.size(); ++i)
        {
            const std::string suffix = particles_.size() > 1 ? "_" + std::to_string(i) : "";
            for (const auto& field : fields_)
            {
                for (const auto& component : components(field))
                {
                    columns.push_back(field + (component.empty() ? "" : "_" + component) + suffix);
                }
            }
        }
        this->setColumns(columns);
    }

    bool distributable() const override { return true; } // ParticleRanks

    void execute(const StepState<D>& state) override
    {
        if (!this->rowDue(state.time, state.deltaT))
        {
            return;
        }
        // Each probe's values come from the rank that owns its particle.
        const ParticleSet<D>& p = state.particles;
        std::size_t width = 0;
        for (const auto& field : fields_)
        {
            width += components(field).size();
        }
        const auto fill = [&](std::size_t a, double* out) {
            for (const auto& field : fields_)
            {
                if (field == "position" || field == "displacement" || field == "velocity")
                {
                    const Vec<D> value = field == "position"       ? p.x[a]
                                         : field == "displacement" ? Vec<D>(p.x[a] - p.X[a])
                                                                   : state.velocity[a];
                    for (int d = 0; d < D; ++d)
                    {
                        *out++ = value[d];
                    }
                }
                else if (field == "F" || field == "P")
                {
                    const Mat<D>& value = field == "F" ? p.F[a] : p.P[a];
                    for (int i = 0; i < D; ++i)
                    {
                        for (int j = 0; j < D; ++j)
                        {
                            *out++ = value(i, j);
                        }
                    }
                }
                else
                {
                    *out++ = p.F[a].determinant();
                }
            }
        };
        const std::vector<double> row = state.rankView().fromOwners(particles_, width, fill);
        this->writeRow(state.time, state.deltaT, row);
    }

private:
    // The nearest particle lies within maxSpacings of its own spacing from the point: a point
    // outside the bodies (x = 1e300 found particle 0; issue 31) probes nothing it names.
    static void checkNear(const Params& params, std::size_t i, const ParticleSet<D>& particles,
                          std::size_t best, const Vec<D>& target, std::size_t begin,
                          std::size_t end)
    {
        constexpr double maxSpacings = 2.0;
        const double spacing = std::pow(particles.V0[best], 1.0 / D);
        const double distance = (particles.X[best] - target).stableNorm(); // 1e300: no overflow
        if (distance <= maxSpacings * spacing)
        {
            return;
        }
        Vec<D> low = particles.X[begin];
        Vec<D> high = particles.X[begin];
        for (std::size_t a = begin; a < end; ++a)
        {
            low = low.cwiseMin(particles.X[a]);
            high = high.cwiseMax(particles.X[a]);
        }
        const auto text = [](const Vec<D>& x)
        {
            std::string words;
            for (int d = 0; d < D; ++d)
            {
                words += (d ? " " : "") + formatNumber(x[d]);
            }
            return "(" + words + ")";
        };
        params.fail("points", i,
                    "probes: the point " + text(target) + " is " + formatNumber(distance) +
                        " m from the nearest particle, " + std::to_string(best) + " at " +
                        text(particles.X[best]) + ": more than " + formatNumber(maxSpacings) +
                        " spacings (" + formatNumber(maxSpacings * spacing) + " m)",
                    {"The particles searched lie between " + text(low) + " and " + text(high) +
                         " m.",
                     "A probe point is an initial position inside a body (or on its surface); "
                     "is a coordinate or its unit wrong?"});
    }

    // The particles found for the points: "particles 39 12".
    std::vector<std::string> summaryExtras() const override
    {
        std::string text = particles_.size() > 1 ? "particles" : "particle";
        for (const auto a : particles_)
        {
            text += " " + std::to_string(a);
        }
        return {text};
    }

    static std::vector<std::string> components(const std::string& field)
    {
        static const char* axes[3] = {"x", "y", "z"};
        std::vector<std::string> result;
        if (field == "J")
        {
            return {""};
        }
        if (field == "F" || field == "P")
        {
            for (int i = 0; i < D; ++i)
            {
                for (int j = 0; j < D; ++j)
                {
                    result.push_back(std::string(axes[i]) + axes[j]);
                }
            }
            return result;
        }
        for (int d = 0; d < D; ++d)
        {
            result.emplace_back(axes[d]);
        }
        return result;
    }

    std::vector<std::string> fields_;
    std::vector<std::size_t> particles_;
};

SPH_REGISTER_DIM_MODEL(FunctionObject, Probes, "probes");

} // namespace sph
