#pragma once
// The inverse of the gradF least-squares matrix Z (spec §6.2), regularised for neighbourhoods
// that no longer span the curvatures (docs/theory/plasticity.md §P11).

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

namespace sph
{

// Z^{-1}, with the eigenvalues of Z/scale (mean 1) raised to at least smallestEigenvalue: a
// neighbourhood that no longer spans the curvatures (a particle with few neighbours, a chain
// of particles: granular flows make them once the reference moves) would otherwise turn
// offsets of round-off size into a huge H_a. Directions no neighbour sees (eigenvalue 0)
// contribute nothing either way: the right-hand side has no component along them.
// Well-conditioned Z (every regular cloud: ≈ 0.25 inside a body, ≥ 0.08 at corners in 2D)
// take Z.inverse() as before, to the bit; Z = 0 (no neighbour) gives H_a = 0.
template <class MatM>
MatM regularisedInverse(const MatM& Z, double scale, double smallestEigenvalue)
{
    if (!(scale > 0.0) || !Z.allFinite())
    {
        return MatM::Zero();
    }
    const MatM normalised = Z / scale;
    // Cholesky of Z/scale - s I succeeds exactly when every eigenvalue exceeds s.
    if (Eigen::LLT<MatM>(normalised - smallestEigenvalue * MatM::Identity()).info() ==
        Eigen::Success)
    {
        return Z.inverse();
    }
    const Eigen::SelfAdjointEigenSolver<MatM> eigen(normalised);
    const typename Eigen::SelfAdjointEigenSolver<MatM>::RealVectorType raised =
        eigen.eigenvalues().cwiseMax(smallestEigenvalue).cwiseInverse() / scale;
    return eigen.eigenvectors() * raised.asDiagonal() * eigen.eigenvectors().transpose();
}

} // namespace sph
