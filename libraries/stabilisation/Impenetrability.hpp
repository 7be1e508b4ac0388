#pragma once
// Impenetrability (system/sphSchemes `impenetrability { distance 0.5; }`): a conservative pair
// energy that keeps particles from pairing where the material carries no stress
// (docs/theory/impenetrability.md). Added to any scheme's force and energy:
//
//   Π_I = Σ_{pairs a<b} ½ M_ab V̄_ab ((d_ab − r_ab)₊ / s_ab)²,                              (I2.1)
//   f_a = Σ_{b≠a} M_ab V̄_ab (d_ab − r_ab)₊ / s_ab² · (x_a − x_b)/r_ab,                      (I3.1)
//
// s = V0^(1/D), d = δ s (pair means), V̄ and M = ρ0 c0² the pair means of the initial volumes
// and of the material's P-wave modulus at F = I. Pairs: the reference neighbour list (§I3).
// Zero wherever no pair is closer than δ spacings, so a case that never pairs is unchanged
// bit for bit; a case without the key pays nothing.

#include "materials/Material.hpp"
#include "particles/Parallel.hpp"
#include "particles/ReferenceConfiguration.hpp"

#include <cmath>
#include <vector>

namespace sph
{

template <int D>
class Impenetrability
{
public:
    // distance: δ ∈ (0, 1]; materials by body (their density and wave speed at F = I).
    Impenetrability(double distance, const std::vector<const Material<D>*>& materials)
        : distance_(distance)
    {
        for (const Material<D>* material : materials)
        {
            const double c0 = material->waveSpeed(Mat<D>::Identity());
            modulus_.push_back(material->density() * c0 * c0);
        }
    }

    double distance() const { return distance_; }

    // Adds f_a (I3.1) to T_a for every particle (gather form: the result does not depend on
    // the number of threads). Returns Π_I (I2.1) of the counted particles (half of each of
    // their pairs) when wantEnergy, else 0.
    double addForces(const std::vector<Vec<D>>& x, const std::vector<double>& V0,
                     const std::vector<int>& body, const ReferenceConfiguration<D>& ref,
                     const std::vector<std::uint8_t>* owned, std::vector<Vec<D>>& T,
                     bool wantEnergy) const
    {
        return visit(x, V0, body, ref, owned, &T, wantEnergy);
    }

    // Π_I alone (I2.1), of the counted particles.
    double energy(const std::vector<Vec<D>>& x, const std::vector<double>& V0,
                  const std::vector<int>& body, const ReferenceConfiguration<D>& ref,
                  const std::vector<std::uint8_t>* owned) const
    {
        return visit(x, V0, body, ref, owned, nullptr, true);
    }

private:
    double visit(const std::vector<Vec<D>>& x, const std::vector<double>& V0,
                 const std::vector<int>& body, const ReferenceConfiguration<D>& ref,
                 const std::vector<std::uint8_t>* owned, std::vector<Vec<D>>* T,
                 bool wantEnergy) const
    {
        const NeighbourList& list = ref.neighbours;
        const std::size_t n = list.particleCount();
        std::vector<double> energy(wantEnergy ? n : 0, 0.0);
#pragma omp parallel for schedule(static) if (useThreads(n))
        for (std::size_t a = 0; a < n; ++a)
        {
            const double sa = rootOfDimension<D>(V0[a]);
            const double Ma = modulus_[static_cast<std::size_t>(body[a])];
            Vec<D> force = Vec<D>::Zero();
            double ea = 0.0;
            bool touched = false;
            for (std::size_t k = list.begin(a) + 1; k < list.end(a); ++k) // the self entry first
            {
                const std::size_t b = list.indices[k];
                const double s = 0.5 * (sa + rootOfDimension<D>(V0[b]));
                const double d = distance_ * s;
                const Vec<D> xab = x[a] - x[b];
                const double r2 = xab.squaredNorm();
                if (r2 >= d * d)
                {
                    continue; // the common case: no energy, no force
                }
                touched = true;
                const double r = std::sqrt(r2);
                const double stiffness = 0.5 * (Ma + modulus_[static_cast<std::size_t>(body[b])]) *
                                         0.5 * (V0[a] + V0[b]) / (s * s);
                const double overlap = d - r;
                ea += 0.25 * stiffness * overlap * overlap; // half of the pair's ½ k overlap²
                if (r > 0.0)
                {
                    force += (stiffness * overlap / r) * xab;
                }
            }
            if (T && touched) // untouched, T keeps its bits (even the sign of a zero)
            {
                (*T)[a] += force;
            }
            if (wantEnergy && (!owned || (*owned)[a]))
            {
                energy[a] = ea;
            }
        }
        double total = 0.0;
        for (double e : energy)
        {
            total += e; // in particle order: independent of the thread count
        }
        return total;
    }

    double distance_;
    std::vector<double> modulus_; // M = ρ0 c0² by body
};

} // namespace sph
