#pragma once
// The Hencky elastic law in principal logarithmic strains (docs/theory/plasticity.md §P2), the
// elastic part of every material with plastic history and, alone, the `hencky` material:
//
//   be = F Cp⁻¹ Fᵀ = Σ λᵢ² nᵢ⊗nᵢ,  εᵢ = ½ ln λᵢ²,  εv = Σ εᵢ,               (P1.1, P2.1)
//   Ψ = μ Σ (εᵢ − εv/3)² + ½ K εv²,  τᵢ = 2μ (εᵢ − εv/3) + K εv,          (P2.2, P2.3)
//   P = τ F⁻ᵀ.                                                            (P2.4)
//
// In 2D (plane strain) be is the in-plane block plus its zz component (the third principal
// direction is z); in 3D the full symmetric tensor. (The 1D bar is uniaxial stress and has its
// own one-line law, §P6: τ = E ε.)

#include "materials/IsotropicElasticity.hpp"
#include "particles/Types.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace sph
{

// A symmetric be in principal form: the three principal log strains and the D in-plane
// eigenvectors (columns; in 2D the third direction is z, in 3D all three).
template <int D>
struct PrincipalStrain
{
    Eigen::Vector3d eps = Eigen::Vector3d::Zero();
    Mat<D> vectors = Mat<D>::Identity();

    // Σᵢ values[i] nᵢ⊗nᵢ over the D in-plane directions.
    Mat<D> assemble(const Eigen::Vector3d& values) const
    {
        Mat<D> result = Mat<D>::Zero();
        for (int i = 0; i < D; ++i)
        {
            result.noalias() += values[i] * vectors.col(i) * vectors.col(i).transpose();
        }
        return result;
    }
};

// The principal logarithmic strains of be (in-plane block `be`, out-of-plane `beZZ` in 2D).
template <int D>
PrincipalStrain<D> principalStrain(const Mat<D>& be, double beZZ = 1.0)
{
    static_assert(D == 2 || D == 3, "the 1D bar is uniaxial stress (§P6)");
    PrincipalStrain<D> p;
    if constexpr (D == 2)
    {
        // Closed form for a symmetric 2×2: eigenvalues m ± r; the eigenvector of m + r from the
        // row of (be - λ I) with the larger norm (no trigonometry: this runs for every sample).
        const double m = 0.5 * (be(0, 0) + be(1, 1));
        const double d = 0.5 * (be(0, 0) - be(1, 1));
        const double b = 0.5 * (be(0, 1) + be(1, 0));
        const double r = std::sqrt(d * d + b * b);
        if (r > 0.0)
        {
            Vec<2> v = d >= 0.0 ? Vec<2>(d + r, b) : Vec<2>(b, r - d);
            v /= v.norm();
            p.vectors << v[0], -v[1], v[1], v[0];
        }
        p.eps << 0.5 * std::log(m + r), 0.5 * std::log(m - r), 0.5 * std::log(beZZ);
    }
    else
    {
        // The iterative solver (tridiagonalisation and implicit QR): the closed-form
        // computeDirect loses half the digits near a double eigenvalue (sqrt(eps) ~ 1e-8),
        // and axisymmetric states such as uniaxial stress have one.
        Eigen::SelfAdjointEigenSolver<Mat<3>> solver(0.5 * (be + be.transpose()));
        p.vectors = solver.eigenvectors();
        for (int i = 0; i < 3; ++i)
        {
            p.eps[i] = 0.5 * std::log(solver.eigenvalues()[i]);
        }
    }
    return p;
}

// The law itself, on principal values.
struct HenckyLaw
{
    double K = 0.0;  // bulk modulus
    double mu = 0.0; // shear modulus

    explicit HenckyLaw(const IsotropicElasticity& c) : K(c.bulkModulus()), mu(c.mu) {}
    HenckyLaw(double bulk, double shear) : K(bulk), mu(shear) {}

    double longitudinalModulus() const { return K + 4.0 * mu / 3.0; }

    // One principal value: τₖ = 2μ eₖ + K εv from the deviator eₖ = εₖ − εv/3 and εv; and the
    // energy μ |e|² + ½ K εv² from |e|² and εv (the plastic models' lanes use them point by
    // point, ReturnMapPlasticity).
    double kirchhoffOf(double dev, double ev) const { return 2.0 * mu * dev + K * ev; }
    double energyOf(double devSquared, double ev) const
    {
        return mu * devSquared + 0.5 * K * ev * ev;
    }

    Eigen::Vector3d kirchhoff(const Eigen::Vector3d& eps) const
    {
        const double ev = eps.sum();
        return 2.0 * mu * (eps - Eigen::Vector3d::Constant(ev / 3.0)) +
               Eigen::Vector3d::Constant(K * ev);
    }
    // The inverse of kirchhoff(): ε = dev τ/(2μ) + tr τ/(9K) (1 1 1).
    Eigen::Vector3d strainOf(const Eigen::Vector3d& tau) const
    {
        const double mean = tau.sum() / 3.0;
        return (tau - Eigen::Vector3d::Constant(mean)) / (2.0 * mu) +
               Eigen::Vector3d::Constant(mean / (3.0 * K));
    }
    double energy(const Eigen::Vector3d& eps) const
    {
        const double ev = eps.sum();
        return mu * (eps - Eigen::Vector3d::Constant(ev / 3.0)).squaredNorm() + 0.5 * K * ev * ev;
    }
};

// ρ0 c² of (P2.5) for an elastic state whose principal stretches are those of F (be = F Fᵀ):
// the principal longitudinal modulus (M − τᵢ)/λᵢ². (A material with history bounds it by
// (M + max|τᵢ|)/λ²_min of the total F instead: j2Plasticity.)
template <int D>
double elasticLongitudinalModulus(const HenckyLaw& law, const PrincipalStrain<D>& p,
                                  const Eigen::Vector3d& tau)
{
    double modulus = 0.0;
    for (int i = 0; i < D; ++i)
    {
        modulus = std::max(modulus, (law.longitudinalModulus() - tau[i]) * std::exp(-2.0 * p.eps[i]));
    }
    return modulus;
}

} // namespace sph
