// gradF's stress samples at F_b(a) = F_a + G_a x^r_ba, and with `sampleVolume particle` the
// F-bar samples F̄_b(a) = (J_a / det F_b(a))^(1/D) F_b(a) with the chain rule that makes the
// force the exact −∂Π/∂x of Σ Ŵ Ψ(F̄) (docs/theory/gradF-plastic.md §G13, §G14). The rest of
// the scheme is GradF.cpp.
#include "stabilisation/gradF/GradF.hpp"

#include <algorithm>
#include <limits>

namespace sph
{

template <int D>
double GradF<D>::fillSamples(const Kinematics& kin, std::size_t count, Scratch& scratch,
                             bool particleVolume, bool measure, bool filled) const
{
    double smallest = std::numeric_limits<double>::infinity();
    if (!filled)
    {
        for (std::size_t j = 0; j < count; ++j)
        {
            scratch.F[j] = kin.F + kin.G.contract(scratch.xr[j]);
        }
    }
    if (!particleVolume && !measure)
    {
        return smallest;
    }
    const double Ja = kin.F.determinant();
    for (std::size_t j = 0; j < count; ++j)
    {
        const double Jb = scratch.F[j].determinant();
        smallest = std::min(smallest, Jb);
        if (particleVolume)
        {
            // An inverted sample has no F̄; it is reported and the run stops (§G13).
            scratch.alpha[j] = Jb > 0.0 ? rootOfDimension<D>(Ja / Jb) : 1.0;
            scratch.F[j] *= scratch.alpha[j];
        }
    }
    return smallest;
}

// ∂Ψ(F̄)/∂F_b = α (P̄ − p̃ F̄^{-T}) and ∂Ψ(F̄)/∂F_a = p̃ F_a^{-T}, p̃ = tr(P̄ F̄ᵀ)/D (§G13 (G13.2)).
template <int D>
double GradF<D>::chainParticleVolume(std::size_t count, Scratch& scratch) const
{
    double pressure = 0.0;
    for (std::size_t j = 0; j < count; ++j)
    {
        const Mat<D>& Fbar = scratch.F[j];
        const double p = (scratch.P[j].array() * Fbar.array()).sum() / D;
        pressure += scratch.w[j] * p;
        scratch.P[j] = scratch.alpha[j] * (scratch.P[j] - p * Fbar.inverse().transpose());
    }
    return pressure;
}

template double GradF<1>::fillSamples(const Kinematics&, std::size_t, Scratch&, bool, bool, bool) const;
template double GradF<2>::fillSamples(const Kinematics&, std::size_t, Scratch&, bool, bool, bool) const;
template double GradF<3>::fillSamples(const Kinematics&, std::size_t, Scratch&, bool, bool, bool) const;
template double GradF<1>::chainParticleVolume(std::size_t, Scratch&) const;
template double GradF<2>::chainParticleVolume(std::size_t, Scratch&) const;
template double GradF<3>::chainParticleVolume(std::size_t, Scratch&) const;

} // namespace sph
