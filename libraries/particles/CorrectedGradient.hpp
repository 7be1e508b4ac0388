#pragma once
// Bonet-Lok corrected gradient (spec §2), in the working form
//   g_a(b) = V_b L_a d_ab (b ≠ a),   g_a(a) = L_a e_a,   e_a = -Σ_{b≠a} V_b d_ab,
//   L_a = M_a^{-T},   M_a = Σ_b V_b x_ba ⊗ d_ab,
// where d_ab is the kernel gradient used for the pair (∇W_ab, or the shifted gradient of the
// `vidal` scheme). Then Σ_b g_a(b) = 0 and Σ_b x_b ⊗ g_a(b) = I hold on any cloud with M_a
// invertible, boundary particles included: ⟨∇φ⟩_a = Σ_b φ_b ⊗ g_a(b) is exact for linear φ.

#include "particles/NeighbourList.hpp"

#include <vector>

namespace sph
{

template <int D>
struct CorrectedGradient
{
    std::vector<Mat<D>> L; // per particle
    std::vector<Vec<D>> e; // per particle

    // Computes L and e from per-pair gradients `d` (aligned with list.indices, self slot
    // ignored). Returns the index of the first particle whose M_a is singular, or -1.
    long build(const NeighbourList& list, const std::vector<Vec<D>>& x,
               const std::vector<double>& V, const std::vector<Vec<D>>& d);
};

} // namespace sph
