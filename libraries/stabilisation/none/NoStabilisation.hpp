#pragma once
// `none`: plain corrected SPH, no stabilisation (spec §3 total-Lagrangian, §4 updated-
// Lagrangian). Π = Σ_a V0_a Ψ(F_a), T_c = -Σ_a V0_a P_a F^r_a^T g_a(c).
// Keys: none. With `updatedLagrangian` this is the scheme that fails on the seed's problems
// (the Dyka bar creeps outward, the rings break): the baseline the paper improves on.

#include "stabilisation/CsphOperators.hpp"

namespace sph
{

template <int D>
class NoStabilisation : public Stabilisation<D>
{
public:
    static std::string description();
    static Schema schema() { return Schema(); }
    NoStabilisation(const Params&, const typename Stabilisation<D>::Args&) {}

    ForceStatus prepare(const ReferenceConfiguration<D>&) override { return {}; }
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
                              bool wantEnergy) override
    {
        return core_.compute(in, out, wantEnergy, StandardGradients<D>{in.ref});
    }
    double energy(const ForceInput<D>& in) override
    {
        return core_.energy(in, StandardGradients<D>{in.ref});
    }

private:
    CsphCore<D> core_;
};

} // namespace sph
