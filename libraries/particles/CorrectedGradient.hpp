#pragma once
// Bonet-Lok corrected gradient (spec §2), in the working form
//   g_a(b) = V_b L_a d_ab (b ≠ a),   g_a(a) = L_a e_a,   e_a = -Σ_{b≠a} V_b d_ab,
//   L_a = M_a^{-T},   M_a = Σ_b V_b x_ba ⊗ d_ab,
// where d_ab is the kernel gradient used for the pair (∇W_ab, or the shifted gradient of the
// `vidal` scheme). Then Σ_b g_a(b) = 0 and Σ_b x_b ⊗ g_a(b) = I hold on any cloud with M_a
// invertible, boundary particles included: ⟨∇φ⟩_a = Σ_b φ_b ⊗ g_a(b) is exact for linear φ.

#include "particles/NeighbourList.hpp"
#include "particles/Parallel.hpp"

#include <cmath>

#include <vector>

namespace sph
{

template <int D>
struct CorrectedGradient
{
    std::vector<Mat<D>> L; // per particle
    std::vector<Vec<D>> e; // per particle

    // Computes L and e from the per-pair gradients d(a, k) (k a slot of a's list; the self
    // slot is ignored). Returns the index of the first particle whose M_a is singular, or -1.
    template <class Gradient>
    long build(const NeighbourList& list, const std::vector<Vec<D>>& x,
               const std::vector<double>& V, const Gradient& d);
};

template <int D>
template <class Gradient>
long CorrectedGradient<D>::build(const NeighbourList& list, const std::vector<Vec<D>>& x,
                                 const std::vector<double>& V, const Gradient& d)
{
    const std::size_t n = list.particleCount();
    L.resize(n);
    e.resize(n);
    long singular = -1;
#pragma omp parallel for schedule(static) reduction(max : singular) if (useThreads(n))
    for (std::size_t a = 0; a < n; ++a)
    {
        Mat<D> M = Mat<D>::Zero();
        Vec<D> sum = Vec<D>::Zero();
        for (std::size_t k = list.begin(a) + 1; k < list.end(a); ++k)
        {
            const std::size_t b = list.indices[k];
            const Vec<D> weighted = V[b] * d(a, k);
            M.noalias() += (x[b] - x[a]) * weighted.transpose();
            sum += weighted;
        }
        // M ≈ I on a regular cloud; a (near-)singular M means too few neighbours or all on a
        // line/plane: the gradient cannot be corrected there.
        const double det = M.determinant();
        if (!(std::abs(det) > 1.0e-8) || !std::isfinite(det))
        {
            singular = std::max<long>(singular, static_cast<long>(n - a)); // max → smallest a
            L[a].setIdentity();
        }
        else
        {
            L[a] = M.inverse().transpose();
        }
        e[a] = -sum;
    }
    return singular < 0 ? -1 : static_cast<long>(n) - singular;
}

} // namespace sph
