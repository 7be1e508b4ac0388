#pragma once
// Nearly incompressible Neo-Hookean, the seed's eq. (36) (spec §8):
//   J = det F,  I1 = tr(F^T F) + (3 - d)   (plane strain / uniaxial strain: the missing
//   stretches are 1),
//   Ψ = ½ μ (J^{-2/3} I1 - 3) + ½ κ (J - 1)^2,
//   P = μ J^{-2/3} (F - (I1/3) F^{-T}) + κ J (J - 1) F^{-T}.
// Keys:
//   mu    | shear modulus μ [Pa]   | required
//   kappa | bulk modulus κ [Pa]    | required
//   rho   | initial density        | required
// Seed rings: μ = 0.3571 MPa, κ = 1.67 MPa (E = 1 MPa, ν = 0.4).
// Wave speed: the principal longitudinal modulus ∂²Ψ/∂λ_i² at the smallest stretch λ,
//   M = ½ μ J^{-2/3} ((10/9) I1/λ^2 - 2/3) + κ J^2/λ^2   (= κ + 4μ/3 at F = I).

#include "materials/IsotropicElasticity.hpp"
#include "materials/Material.hpp"
#include "particles/FastMath.hpp"

namespace sph
{

template <int D>
class NeoHookean : public MaterialModel<D, NeoHookean<D>>
{
public:
    static std::string description();
    static Schema schema();
    NeoHookean(const Params& params, const typename Material<D>::Args& args);

    // With cof F = J F^{-T} and c = J^{-1/3} (so 1/J = c^3, no division):
    //   P = a F + b cof F,  a = μ c²,  b = κ (J - 1) - a I1 c³/3.
    // The cofactor is written out (one determinant, no general inverse): this is evaluated
    // for every neighbour of every particle by the gradient-of-F scheme.
    Mat<D> stressOf(const Mat<D>& F) const
    {
        const Mat<D> C = cofactor(F);
        const double J = (F.col(0).dot(C.col(0)));
        const double I1 = F.squaredNorm() + (3 - D);
        const double c = inverseCubeRoot(J);
        const double a = mu_ * c * c;
        const double b = kappa_ * (J - 1.0) - a * I1 * (c * c * c) * (1.0 / 3.0);
        return a * F + b * C;
    }
    double energyOf(const Mat<D>& F) const
    {
        const double J = F.determinant();
        const double I1 = F.squaredNorm() + (3 - D);
        const double c = inverseCubeRoot(J);
        return 0.5 * mu_ * (c * c * I1 - 3.0) + 0.5 * kappa_ * (J - 1.0) * (J - 1.0);
    }
    double waveSpeedOf(const Mat<D>& F) const
    {
        const double J = F.determinant();
        const double I1 = F.squaredNorm() + (3 - D);
        const double lowest = stretchSquaredRange<D>(F).first;
        const double c = inverseCubeRoot(J);
        const double modulus = 0.5 * mu_ * c * c * ((10.0 / 9.0) * I1 / lowest - 2.0 / 3.0) +
                               kappa_ * J * J / lowest;
        return std::sqrt(std::max(modulus, 0.0) / this->density());
    }
    double youngsModulus() const override
    {
        return IsotropicElasticity::fromBulkAndShear(kappa_, mu_).E;
    }

    // The same for n gradients at once, in structure-of-arrays form so the compiler vectorises
    // the scalar part (J, I1, J^{-1/3}): the gradient-of-F scheme evaluates a stress for every
    // neighbour of every particle. Identical to stressOf up to round-off.
    void stressBatch(const Mat<D>* F, Mat<D>* P, std::size_t n) const
    {
        constexpr std::size_t block = 64;
        double f[D * D][block];
        double a[block];
        double b[block];
        for (std::size_t start = 0; start < n; start += block)
        {
            const std::size_t count = std::min(block, n - start);
            for (std::size_t i = 0; i < count; ++i)
            {
                for (int k = 0; k < D * D; ++k)
                {
                    f[k][i] = F[start + i](k / D, k % D);
                }
            }
#pragma omp simd
            for (std::size_t i = 0; i < count; ++i)
            {
                double J;
                double I1 = 3 - D;
                for (int k = 0; k < D * D; ++k)
                {
                    I1 += f[k][i] * f[k][i];
                }
                if constexpr (D == 1)
                {
                    J = f[0][i];
                }
                else if constexpr (D == 2)
                {
                    J = f[0][i] * f[3][i] - f[1][i] * f[2][i];
                }
                else
                {
                    J = f[0][i] * (f[4][i] * f[8][i] - f[5][i] * f[7][i]) -
                        f[1][i] * (f[3][i] * f[8][i] - f[5][i] * f[6][i]) +
                        f[2][i] * (f[3][i] * f[7][i] - f[4][i] * f[6][i]);
                }
                const double c = inverseCubeRoot(J);
                a[i] = mu_ * c * c;
                b[i] = kappa_ * (J - 1.0) - a[i] * I1 * (c * c * c) * (1.0 / 3.0);
            }
            for (std::size_t i = 0; i < count; ++i)
            {
                const Mat<D>& Fi = F[start + i];
                P[start + i] = a[i] * Fi + b[i] * cofactor(Fi);
            }
        }
    }

private:
    // cof F = det(F) F^{-T}
    static Mat<D> cofactor(const Mat<D>& F)
    {
        Mat<D> C;
        if constexpr (D == 1)
        {
            C(0, 0) = 1.0;
        }
        else if constexpr (D == 2)
        {
            C << F(1, 1), -F(1, 0), -F(0, 1), F(0, 0);
        }
        else
        {
            C.col(0) = F.col(1).cross(F.col(2));
            C.col(1) = F.col(2).cross(F.col(0));
            C.col(2) = F.col(0).cross(F.col(1));
        }
        return C;
    }

    double mu_;
    double kappa_;
};

} // namespace sph
