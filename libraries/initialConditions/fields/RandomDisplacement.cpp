// `random` initial displacement field (x = X + u at t = 0; see Fields.hpp).
//   amplitude, seed    u = amplitude · (uniform in [-1, 1])^D
#include "initialConditions/fields/Fields.hpp"

#include <random>

namespace sph
{

template <int D>
class RandomDisplacement : public DisplacementField<D>
{
public:
    static std::string description() { return "Uniform random noise of a given amplitude (reproducible: seeded)."; }
    static Schema schema()
    {
        return Schema()
            .add(Key::real("amplitude", "largest displacement per component [m]").nonNegative())
            .add(Key::integer("seed", "random seed").min(0).defaultValue("1"));
    }
    RandomDisplacement(const Params& p, const typename DisplacementField<D>::Args&)
        : amplitude_(p.real("amplitude")), seed_(static_cast<unsigned>(p.integer("seed")))
    {
    }
    Vec<D> displacement(const Vec<D>&, std::size_t particle) const override
    {
        // A generator per particle: the noise does not depend on the order of the calls.
        std::mt19937_64 random(seed_ * 1000003ULL + particle);
        std::uniform_real_distribution<double> uniform(-1.0, 1.0);
        Vec<D> u;
        for (int d = 0; d < D; ++d)
        {
            u[d] = amplitude_ * uniform(random);
        }
        return u;
    }

private:
    double amplitude_;
    unsigned seed_;
};

SPH_REGISTER_DIM_MODEL(DisplacementField, RandomDisplacement, "random");

} // namespace sph
