#pragma once
// gradF's stress samples at moment points (`samplePoints moments`, docs/theory/gradF-moments.md):
// 2D + 1 points with the zeroth, first and second moments of a particle's kernel weights, so
// that Σ_q ω_q Ψ(F + G ξ_q) = Σ_b Ŵ_ab Ψ(F + G x^r_ba) for every Ψ quadratic in F (§M1-§M2).

#include "particles/Types.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace sph
{

template <int D>
struct MomentPoints
{
    static constexpr int count = 2 * D + 1;
    // The particle's own weight inside a body, 1 - D/3: along each axis of a neighbourhood with
    // a diagonal covariance the points then have a Gaussian's fourth moment (§M2).
    static constexpr double particleWeight = 1.0 - D / 3.0;
};

// The points ξ_q and weights ω_q of (M3) from the offsets xr[j] = x^r_ba and weights w[j] = Ŵ_ab
// of one particle's neighbours (j = 0 the particle itself, xr[0] = 0). Point 0 is the particle
// (ξ_0 = 0), then the pairs μ ± √D L e_k. Returns false, writing nothing, where the rule does
// not apply (§M2): fewer than 2D + 1 neighbours, or a covariance that is not positive definite.
template <int D>
bool momentPoints(const Vec<D>* xr, const double* w, std::size_t neighbours, Vec<D>* points,
                  double* weights)
{
    if (neighbours < static_cast<std::size_t>(MomentPoints<D>::count))
    {
        return false;
    }
    double total = 0.0;
    Vec<D> first = Vec<D>::Zero();
    Mat<D> second = Mat<D>::Zero();
    for (std::size_t j = 0; j < neighbours; ++j)
    {
        total += w[j];
        first += w[j] * xr[j];
        second.noalias() += (w[j] * xr[j]) * xr[j].transpose();
    }
    if (!(total > 0.0))
    {
        return false;
    }
    const Vec<D> m = first / total;
    const Mat<D> M = second / total;
    const Eigen::LLT<Mat<D>> secondFactor(M);
    if (secondFactor.info() != Eigen::Success)
    {
        return false;
    }
    // ω_0 ≤ ½ (1 − mᵀ M⁻¹ m) keeps M − m mᵀ/(1 − ω_0) well away from singular (Schur complement).
    const double offCentre = m.dot(secondFactor.solve(m));
    const double omega0 = std::min(MomentPoints<D>::particleWeight, 0.5 * (1.0 - offCentre));
    if (!(omega0 >= 0.0))
    {
        return false;
    }
    const double rest = 1.0 - omega0;
    const Eigen::LLT<Mat<D>> spread((M - m * m.transpose() / rest) / rest);
    if (spread.info() != Eigen::Success)
    {
        return false;
    }
    const Mat<D> L = spread.matrixL();
    const Vec<D> mu = m / rest;
    const double reach = std::sqrt(static_cast<double>(D));
    points[0] = Vec<D>::Zero();
    weights[0] = total * omega0;
    for (int k = 0; k < D; ++k)
    {
        const Vec<D> axis = reach * L.col(k);
        points[1 + 2 * k] = mu + axis;
        points[2 + 2 * k] = mu - axis;
        weights[1 + 2 * k] = total * rest / (2.0 * D);
        weights[2 + 2 * k] = total * rest / (2.0 * D);
    }
    return true;
}

// The axes A of a particle's points (columns, ξ_{±k} = μ ± A e_k): ½ (ξ_{+k} − ξ_{−k}).
template <int D>
Mat<D> momentAxes(const Vec<D>* points)
{
    Mat<D> axes;
    for (int k = 0; k < D; ++k)
    {
        axes.col(k) = 0.5 * (points[1 + 2 * k] - points[2 + 2 * k]);
    }
    return axes;
}

// The points of (M3) on other axes A with the same A Aᵀ (the same moments, §M2).
template <int D>
void turnMomentPoints(Vec<D>* points, const Mat<D>& axes)
{
    const Vec<D> mu = 0.5 * (points[1] + points[2]);
    for (int k = 0; k < D; ++k)
    {
        points[1 + 2 * k] = mu + axes.col(k);
        points[2 + 2 * k] = mu - axes.col(k);
    }
}

// The orthogonal factor R of the polar decomposition X = R P (P symmetric positive definite):
// the orthogonal matrix closest to X, the maximiser of tr(Rᵀ X). In 2D in closed form (the
// better of the rotations and the reflections, each a maximum over one angle), else by the
// scaled Newton iteration R ← ½ (γ R + R⁻ᵀ/γ), γ = (‖R⁻¹‖/‖R‖)^(1/2) (quadratic convergence).
// X must be invertible.
template <int D>
Mat<D> orthogonalPolarFactor(const Mat<D>& X)
{
    if constexpr (D == 1)
    {
        return Mat<D>::Constant(X(0, 0) < 0.0 ? -1.0 : 1.0);
    }
    else if constexpr (D == 2)
    {
        const double rc = X(0, 0) + X(1, 1), rs = X(1, 0) - X(0, 1); // rotations
        const double fc = X(0, 0) - X(1, 1), fs = X(1, 0) + X(0, 1); // reflections
        Mat<D> R;
        if (std::hypot(rc, rs) >= std::hypot(fc, fs))
        {
            const double n = std::hypot(rc, rs);
            R << rc / n, -rs / n, rs / n, rc / n;
        }
        else
        {
            const double n = std::hypot(fc, fs);
            R << fc / n, fs / n, fs / n, -fc / n;
        }
        return R;
    }
    else
    {
        Mat<D> R = X;
        for (int iteration = 0; iteration < 50; ++iteration)
        {
            const Mat<D> inverse = R.inverse();
            const double gamma = std::sqrt(std::sqrt(inverse.squaredNorm() / R.squaredNorm()));
            const Mat<D> next = 0.5 * (gamma * R + inverse.transpose() / gamma);
            const double change = (next - R).norm();
            R = next;
            if (change <= 1.0e-15 * std::sqrt(static_cast<double>(D)))
            {
                break;
            }
        }
        return R;
    }
}

// The axes closest to `carried` (the old axes moved with the material, f_a A) among those of a
// rule whose Cholesky axes are C = √D L, which are C U for every orthogonal U (their product
// with their transpose is D Σ): A' = C R, R the orthogonal polar factor of Cᵀ carried (M7.2).
// If the motion turned the neighbourhood rigidly, the turned old axes are among the rule's, and
// are the ones chosen.
template <int D>
Mat<D> carriedAxes(const Mat<D>& cholesky, const Mat<D>& carried)
{
    const Mat<D> X = cholesky.transpose() * carried;
    if (!(std::abs(X.determinant()) > 0.0))
    {
        return cholesky;
    }
    return cholesky * orthogonalPolarFactor<D>(X);
}

} // namespace sph
