// `line` (1D): n particles from `start` to `end`, both ends included, spacing (end-start)/(n-1).
// Keys:
//   start      | position of the first particle [m]                       | required
//   end        | position of the last particle [m]                        | required
//   n          | number of particles, both ends included                  | required
//   endVolumes | half: end particles get half a spacing, so the volumes tile [start, end]
//              | exactly; full: every particle gets a whole spacing        | half
#include "initialConditions/generators/Generator.hpp"

#include <cmath>

namespace sph
{

template <int D>
class Line : public Generator<D>
{
public:
    static std::string description()
    {
        return "1D bar: n particles from start to end (both included); end volumes half "
               "(default, tiles the bar exactly) or full.";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::real("start", "position of the first particle [m]"))
            .add(Key::real("end", "position of the last particle [m]"))
            .add(Key::integer("n", "number of particles, both ends included").min(2))
            .add(Key::word("endVolumes", "volume of the two end particles")
                     .choices({"half", "full"})
                     .defaultValue("half"));
    }
    Line(const Params& p, const typename Generator<D>::Args&)
        : start_(p.real("start")), end_(p.real("end")), n_(p.integer("n")),
          halfEnds_(p.word("endVolumes") == "half")
    {
        if (!(end_ > start_))
        {
            p.fail("end", "line: 'end' must be greater than 'start'");
        }
        if (!std::isfinite(end_ - start_))
        {
            p.fail("end",
                   "line: from start " + formatNumber(start_) + " to end " + formatNumber(end_) +
                       " m is longer than a number holds (" + formatNumber(end_ - start_) + ")",
                   {"The bar's length end - start must be a finite number of metres; is an "
                    "exponent wrong?"});
        }
        checkParticleCount(p, "n", "line", "n = " + std::to_string(n_) + " makes",
                           static_cast<double>(n_), "Choose a smaller n.");
    }
    GeneratedBody<D> generate() const override
    {
        GeneratedBody<D> body;
        body.spacing = (end_ - start_) / static_cast<double>(n_ - 1);
        for (long i = 0; i < n_; ++i)
        {
            Vec<D> x;
            x[0] = i == n_ - 1 ? end_ : start_ + body.spacing * static_cast<double>(i);
            body.X.push_back(x);
            const bool end = i == 0 || i == n_ - 1;
            body.V.push_back(end && halfEnds_ ? 0.5 * body.spacing : body.spacing);
        }
        return body;
    }

private:
    double start_;
    double end_;
    long n_;
    bool halfEnds_;
};

SPH_REGISTER_DIM_MODEL_FOR(Generator, Line, "line", 1);

} // namespace sph
