#pragma once
// Bonet-Lok corrected gradient (spec §2), in the working form
//   g_a(b) = V_b L_a d_ab (b ≠ a),   g_a(a) = L_a e_a,   e_a = -Σ_{b≠a} V_b d_ab,
//   L_a = M_a^{-T},   M_a = Σ_b V_b x_ba ⊗ d_ab,
// where d_ab is the kernel gradient used for the pair (∇W_ab, or the shifted gradient of the
// `vidal` scheme). Then Σ_b g_a(b) = 0 and Σ_b x_b ⊗ g_a(b) = I hold on any cloud with M_a
// invertible, boundary particles included: ⟨∇φ⟩_a = Σ_b φ_b ⊗ g_a(b) is exact for linear φ.
//
// Deficient supports. Where the neighbours of a no longer span every direction (a particle
// that separates from its body, a layer one particle thick: granular flows make both), M_a is
// (near-)singular and M_a^{-T} would amplify every tiny offset across the layer into a huge
// gradient. There the singular values of M_a below `smallestSingularValue` are raised to it
// (M_a = U Σ V^T, L_a = U Σ'^{-1} V^T, Σ' = max(Σ, s_min)): the gradient is exact for linear
// fields along the directions the neighbours span and damped across the others. The
// deformation gradient is then completed with the part of the identity L_a cannot see,
//   f_a = [Σ_{b≠a} V_b x_ba ⊗ d_ab] L_a^T + C_a,   C_a = I − M_a L_a^T = U (I − Σ Σ'^{-1}) U^T,
// so f_a = I at the reference and f_a = I for a particle with no neighbours at all (it moves
// freely, carrying no force). C_a = 0 for a well-conditioned M_a (f_a as before, to the bit);
// ∂f_a/∂x_b = g_a(b) either way, so forces stay the exact derivative of the energy and
// Σ_b g_a(b) = 0 keeps momentum. (Angular momentum is exact only where C_a = 0: a rotated
// deficient neighbourhood keeps the un-rotated C_a.)

#include "particles/NeighbourList.hpp"
#include "particles/Parallel.hpp"

#include <Eigen/SVD>

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace sph
{

template <int D>
struct CorrectedGradient
{
    // M ≈ I inside a body; its singular values are ≈ 0.5 at a flat free surface, ≈ 0.25 at a
    // right-angled corner of a lattice, and down to 0.047 at corners of the randomly perturbed
    // 3D lattices of the scheme tests (hOverDx 1.6). A fiftieth is a support that has lost a
    // direction (a chain of particles, a particle that left its body).
    static constexpr double smallestSingularValue = 0.02;

    std::vector<Mat<D>> L;          // per particle
    std::vector<Vec<D>> e;          // per particle
    std::vector<Mat<D>> complement; // C_a per particle; empty when every M_a is well-conditioned
    std::size_t deficient = 0;      // how many particles have C_a ≠ 0

    // Computes L, e and C from the per-pair gradients d(a)(k) (d(a) gives particle a's, k a
    // slot of a's list; the self slot is ignored). Returns the index of the first particle whose M_a is singular (det
    // below 1e-8: too few neighbours to span every direction), or -1; such particles get the
    // regularised L_a and C_a too. With `counted` (a distributed run's owned particles), only
    // those are reported: a ghost's neighbourhood may be cut at the edge of its rank's particles.
    template <class Gradient>
    long build(const NeighbourList& list, const std::vector<Vec<D>>& x,
               const std::vector<double>& V, const Gradient& d,
               const std::vector<std::uint8_t>* counted = nullptr);

    // f_a = moment_a L_a^T + C_a from moment_a = Σ_{b≠a} V_b x_ba ⊗ d_ab at the current x.
    Mat<D> deformation(std::size_t a, const Mat<D>& moment) const
    {
        Mat<D> f = moment * L[a].transpose();
        if (!complement.empty())
        {
            f += complement[a];
        }
        return f;
    }
};

template <int D>
template <class Gradient>
long CorrectedGradient<D>::build(const NeighbourList& list, const std::vector<Vec<D>>& x,
                                 const std::vector<double>& V, const Gradient& d,
                                 const std::vector<std::uint8_t>* counted)
{
    const std::size_t n = list.particleCount();
    L.resize(n);
    e.resize(n);
    std::vector<std::pair<std::size_t, Mat<D>>> found; // C_a of the few deficient particles
    long singular = -1;
#pragma omp parallel for schedule(static) reduction(max : singular) if (useThreads(n))
    for (std::size_t a = 0; a < n; ++a)
    {
        Mat<D> M = Mat<D>::Zero();
        Vec<D> sum = Vec<D>::Zero();
        const auto da = d(a);
        for (std::size_t k = list.begin(a) + 1; k < list.end(a); ++k)
        {
            const std::size_t b = list.indices[k];
            const Vec<D> weighted = V[b] * da(k);
            M.noalias() += (x[b] - x[a]) * weighted.transpose();
            sum += weighted;
        }
        e[a] = -sum;
        // M ≈ I on a regular cloud; a (near-)singular M means too few neighbours or all on a
        // line/plane: the gradient cannot be corrected in every direction there.
        const double det = M.determinant();
        if ((!(std::abs(det) > 1.0e-8) || !std::isfinite(det)) && (!counted || (*counted)[a]))
        {
            singular = std::max<long>(singular, static_cast<long>(n - a)); // max → smallest a
        }
        // σ_min ≥ |det M| / σ_max^(D-1) ≥ |det M| / |M|_F^(D-1): most particles skip the SVD.
        const double norm = M.norm();
        if (std::isfinite(det) && std::abs(det) > 0.0 &&
            std::abs(det) >= smallestSingularValue * std::pow(norm, D - 1))
        {
            L[a] = M.inverse().transpose();
            continue;
        }
        if (!M.allFinite())
        {
            M.setZero(); // a neighbour at a non-finite position: treated as no neighbour
        }
        const Eigen::JacobiSVD<Mat<D>> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
        const Vec<D> sigma = svd.singularValues();
        if (sigma[D - 1] >= smallestSingularValue) // sorted: the screen was only a bound
        {
            L[a] = M.inverse().transpose();
            continue;
        }
        Vec<D> inverse;
        Vec<D> unseen; // 1 − σ/σ': the part of each direction L_a cannot see
        for (int i = 0; i < D; ++i)
        {
            inverse[i] = 1.0 / std::max(sigma[i], smallestSingularValue);
            unseen[i] = 1.0 - sigma[i] * inverse[i];
        }
        L[a] = svd.matrixU() * inverse.asDiagonal() * svd.matrixV().transpose();
        const Mat<D> C = svd.matrixU() * unseen.asDiagonal() * svd.matrixU().transpose();
#pragma omp critical(sphDeficientSupports)
        found.emplace_back(a, C);
    }
    deficient = found.size();
    complement.clear();
    if (deficient > 0)
    {
        complement.assign(n, Mat<D>::Zero());
        for (const auto& [a, C] : found)
        {
            complement[a] = C;
        }
    }
    return singular < 0 ? -1 : static_cast<long>(n) - singular;
}

} // namespace sph
