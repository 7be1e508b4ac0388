// Initial displacement fields u(X) (x = X + u at t = 0; see Fields.hpp), one line each below.
//   affine       gradient (D rows), origin        u = (F0 - I)(X - origin): a held stretch
//   random       amplitude, seed                  u = amplitude · (uniform in [-1, 1])^D
//   checkerboard amplitude, spacing, direction,   u = amplitude (-1)^(Σ_d round((X_d - o_d)/spacing))
//                origin                             · direction/|direction|: the zero-energy pattern
#include "particles/fields/Fields.hpp"

#include <cmath>
#include <random>

namespace sph
{

template <int D>
class AffineDisplacement : public DisplacementField<D>
{
public:
    static std::string description() { return "u = (F0 - I)(X - origin): a homogeneous deformation."; }
    static Schema schema()
    {
        return Schema()
            .add(Key::vectorList("gradient", "the deformation gradient F0, one row per dimension, "
                                             "e.g. ((1.1 0) (0 1.1))"))
            .add(Key::vector("origin", "the point that stays [m]").defaultValue("0"));
    }
    AffineDisplacement(const Params& p, const typename DisplacementField<D>::Args&)
        : origin_(toVec<D>(p.vector("origin")))
    {
        const auto& rows = p.vectorList("gradient");
        if (static_cast<int>(rows.size()) != D)
        {
            p.fail("gradient", "affine: 'gradient' needs " + std::to_string(D) + " rows, found " +
                                   std::to_string(rows.size()));
        }
        for (int i = 0; i < D; ++i)
        {
            F0_.row(i) = toVec<D>(rows[static_cast<std::size_t>(i)]).transpose();
        }
        if (!(F0_.determinant() > 0.0))
        {
            p.fail("gradient", "affine: det F0 must be positive");
        }
    }
    Vec<D> displacement(const Vec<D>& X, std::size_t) const override
    {
        return (F0_ - Mat<D>::Identity()) * (X - origin_);
    }

private:
    Mat<D> F0_;
    Vec<D> origin_;
};

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

template <int D>
class CheckerboardDisplacement : public DisplacementField<D>
{
public:
    static std::string description()
    {
        return "Alternating +/- displacement from lattice site to lattice site (the hourglass / "
               "zero-energy pattern).";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::real("amplitude", "displacement [m]"))
            .add(Key::real("spacing", "the lattice spacing [m]").positive())
            .add(Key::vector("direction", "direction of the displacement"))
            .add(Key::vector("origin", "a lattice site [m]").defaultValue("0"));
    }
    CheckerboardDisplacement(const Params& p, const typename DisplacementField<D>::Args&)
        : amplitude_(p.real("amplitude")), spacing_(p.real("spacing")),
          direction_(toVec<D>(p.vector("direction"))), origin_(toVec<D>(p.vector("origin")))
    {
        if (direction_.norm() == 0.0)
        {
            p.fail("direction", "checkerboard: 'direction' must not be zero");
        }
        direction_.normalize();
    }
    Vec<D> displacement(const Vec<D>& X, std::size_t) const override
    {
        long sum = 0;
        for (int d = 0; d < D; ++d)
        {
            sum += std::lround((X[d] - origin_[d]) / spacing_);
        }
        return (sum % 2 == 0 ? amplitude_ : -amplitude_) * direction_;
    }

private:
    double amplitude_;
    double spacing_;
    Vec<D> direction_;
    Vec<D> origin_;
};

SPH_REGISTER_DIM_MODEL(DisplacementField, AffineDisplacement, "affine");
SPH_REGISTER_DIM_MODEL(DisplacementField, RandomDisplacement, "random");
SPH_REGISTER_DIM_MODEL(DisplacementField, CheckerboardDisplacement, "checkerboard");

} // namespace sph
