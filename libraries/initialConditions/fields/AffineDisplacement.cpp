// `affine` initial displacement field (x = X + u at t = 0; see Fields.hpp).
//   gradient (D rows), origin    u = (F0 - I)(X - origin): a held stretch
#include "initialConditions/fields/Fields.hpp"

#include <string>

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

SPH_REGISTER_DIM_MODEL(DisplacementField, AffineDisplacement, "affine");

} // namespace sph
