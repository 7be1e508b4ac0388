#pragma once
// `hourglass`: Ganzenmüller's hourglass control (2015, arXiv:1410.7221), spec §5.2 and §12.
// Plain CSPH plus, for every pair (a, b) of a body in the reference configuration,
//   γ_ab = ½ (f_a + f_b) x^r_ba - x_ba        (error of the f-predicted bond)
//   δ_ab = ½ γ_ab · x_ba / |x_ba|
//   f^HG_a += -α E V0_a V0_b W_ab δ_ab / |x^r_ba|^2 · x_ba / |x_ba|,   f^HG_b = -f^HG_a,
// with f = F in total-Lagrangian form and E the body's Young's modulus. Each unordered pair is
// counted once (`alpha` is twice the coefficient of codes that visit ordered pairs).
// The pair forces are not the gradient of an energy: the `energy` reported is the CSPH Π, and
// the work of the hourglass forces shows up as energy drift.
//
// Keys:
//   alpha | hourglass stiffness α_HG (dimensionless; 10-50 usual, problem dependent) | 10

#include "stabilisation/CsphOperators.hpp"

namespace sph
{

template <int D>
class Hourglass : public Stabilisation<D>
{
public:
    static std::string description();
    static Schema schema();
    Hourglass(const Params& params, const typename Stabilisation<D>::Args& args);

    ForceStatus prepare(const ReferenceConfiguration<D>&) override { return {}; }
    ReferenceNeeds referenceNeeds(const Kernel& kernel) const override
    {
        return {kernel.supportRadius(), false, true};
    }
    ForceStatus referenceUpdate(const std::vector<Vec<D>>& x, const ReferenceConfiguration<D>& ref,
                                std::vector<Mat<D>>& F, std::vector<Tensor3<D>>*) const override
    {
        return core_.deformationGradients(x, ref, StandardGradients<D>{ref}, F);
    }
    Mat<D> deformationGradient(std::size_t a, const std::vector<Vec<D>>& x,
                               const ReferenceConfiguration<D>& ref) const override
    {
        return incrementalGradient<D>(a, x, ref, StandardGradients<D>{ref}) * ref.F[a];
    }
    ForceStatus computeForces(const ForceInput<D>& in, ForceOutput<D>& out,
                              bool wantEnergy) override;
    double energy(const ForceInput<D>& in) override
    {
        return core_.energy(in, StandardGradients<D>{in.ref});
    }
    bool vanishesAtReference() const override { return true; }

    // The hourglass force on particle a alone (public for the pairwise test).
    Vec<D> hourglassForce(std::size_t a, const ForceInput<D>& in,
                          const std::vector<Mat<D>>& f) const;

private:
    double alpha_;
    CsphCore<D> core_;
    std::vector<Mat<D>> f_;
};

} // namespace sph
