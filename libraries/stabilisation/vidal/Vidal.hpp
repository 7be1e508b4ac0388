#pragma once
// `vidal`: a stabilised corrected gradient with a dimensionless vector parameter beta
// (spec §5.1, §12).
//
// THIS IS THIS PROJECT'S REALISATION of the idea the seed paper attributes to Vidal, Bonet &
// Huerta (2007) — a stabilisation term added to the CSPH corrected gradient, containing a
// problem-dependent vector parameter. The 2007 formula itself was not available to us. Here
// the corrected gradient of particle a is evaluated at the shifted point p_a = x^r_a + h beta:
//   g~_a(b) = V_b L~_a [∇W(p_a - x^r_b) + ε~_a δ_ab],
// with L~_a, ε~_a chosen as in spec §2 so that Σ_b g~_a(b) = 0 and Σ_b x^r_b ⊗ g~_a(b) = I
// still hold. To first order this adds (h beta·∇) g_a(b). The energy is Σ_a V0_a Ψ(F~_a), so
// the force is -∂Π/∂x again; beta = 0 reproduces `none` exactly.
//
// Keys:
//   beta | shift of the evaluation point in units of h (|beta| < 1) | 0.1 in every component
//
// The neighbour search reaches (support + |beta|) h. The parameter's effect depends on h and
// on the problem (spec §5.1) — which is the seed paper's criticism of such terms.

#include "stabilisation/CsphOperators.hpp"

namespace sph
{

template <int D>
class Vidal : public Stabilisation<D>
{
public:
    static std::string description();
    static Schema schema();
    Vidal(const Params& params, const typename Stabilisation<D>::Args& args);

    ReferenceNeeds referenceNeeds(const Kernel& kernel) const override
    {
        return {kernel.supportRadius() + beta_.norm() * kernel.h(), false, false};
    }
    ForceStatus prepare(const ReferenceConfiguration<D>& ref) override;
    ForceStatus referenceUpdate(const std::vector<Vec<D>>& x, const ReferenceConfiguration<D>& ref,
                                std::vector<Mat<D>>& F, std::vector<Tensor3<D>>*) const override
    {
        return core_.deformationGradients(x, ref, gradients(), F);
    }
    Mat<D> deformationGradient(std::size_t a, const std::vector<Vec<D>>& x,
                               const ReferenceConfiguration<D>& ref) const override
    {
        return incrementalGradient<D>(a, x, ref, gradients()) * ref.F[a];
    }
    ForceStatus computeForces(const ForceInput<D>& in, ForceOutput<D>& out,
                              bool wantEnergy) override
    {
        return core_.compute(in, out, wantEnergy, gradients());
    }
    double energy(const ForceInput<D>& in) override { return core_.energy(in, gradients()); }

    const Vec<D>& beta() const { return beta_; }

private:
    // The shifted gradients of every pair.
    StoredGradients<D> gradients() const { return {out_, in_, corrected_}; }

    const Kernel& kernel_;
    Vec<D> beta_;
    std::vector<Vec<D>> out_;
    std::vector<Vec<D>> in_;
    CorrectedGradient<D> corrected_;
    CsphCore<D> core_;
};

} // namespace sph
