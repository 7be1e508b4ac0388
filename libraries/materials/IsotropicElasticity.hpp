#pragma once
// Isotropic elastic constants from Young's modulus E and Poisson's ratio ν (spec §8): the one
// place for the keys `E` and `nu` and the conversions of the materials parametrised by them
// (linearElastic, stVenantKirchhoff).
//
//   μ = E / (2 (1 + ν))                          shear modulus (Lamé's second constant)
//   λ = E ν / ((1 + ν)(1 - 2ν))                  Lamé's first constant (3D and plane strain)
//   K = λ + 2μ/3 = E / (3 (1 - 2ν))              bulk modulus
//   M = λ + 2μ = E (1 - ν) / ((1 + ν)(1 - 2ν))   longitudinal (P-wave) modulus
//   c = sqrt(M / ρ0)                             longitudinal wave speed
// and back from K and μ:  E = 9 K μ / (3 K + μ),  ν = (3 K - 2 μ) / (2 (3 K + μ)).
//
// In 1D (a bar in uniaxial stress) only E is used: the modulus of the wave equation is E, and
// `nu` may be left out; in 2D (plane strain) and 3D `nu` is required.
//
// Keys:
//   E  | Young's modulus [Pa]                                    | required
//   nu | Poisson's ratio, in (-1, 0.5) (2D and 3D; unused in 1D) | required in 2D/3D

#include "core/Registry.hpp"

#include <string>

namespace sph
{

struct IsotropicElasticity
{
    double E = 0.0;      // Young's modulus
    double nu = 0.0;     // Poisson's ratio
    double lambda = 0.0; // λ
    double mu = 0.0;     // μ

    static IsotropicElasticity fromYoung(double young, double poisson)
    {
        IsotropicElasticity c;
        c.E = young;
        c.nu = poisson;
        c.mu = young / (2.0 * (1.0 + poisson));
        c.lambda = young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson));
        return c;
    }
    static IsotropicElasticity fromBulkAndShear(double bulk, double shear)
    {
        IsotropicElasticity c;
        c.E = 9.0 * bulk * shear / (3.0 * bulk + shear);
        c.nu = (3.0 * bulk - 2.0 * shear) / (2.0 * (3.0 * bulk + shear));
        c.mu = shear;
        c.lambda = bulk - 2.0 * shear / 3.0;
        return c;
    }

    double bulkModulus() const { return lambda + 2.0 * mu / 3.0; }
    // M = λ + 2μ: the small-strain modulus of a longitudinal wave (2D plane strain, 3D).
    double longitudinalModulus() const { return lambda + 2.0 * mu; }
    // The small-strain longitudinal modulus of a D-dimensional case: E for the 1D bar, M else.
    template <int D>
    double waveModulus() const
    {
        return D == 1 ? E : longitudinalModulus();
    }

    // The keys E and nu, added to a material's schema.
    static Schema schema()
    {
        return Schema()
            .add(Key::real("E", "Young's modulus [Pa]").positive())
            .add(Key::real("nu", "Poisson's ratio (2D plane strain and 3D; unused in 1D)")
                     .range(-1.0, 0.5, false, false)
                     .optional());
    }

    // The constants of validated params (`schema()` keys) in a D-dimensional case: ν is required
    // in 2D and 3D; in 1D only E is read and λ = μ = 0.
    template <int D>
    static IsotropicElasticity read(const Params& params)
    {
        if constexpr (D == 1)
        {
            IsotropicElasticity c;
            c.E = params.real("E");
            return c;
        }
        else
        {
            if (!params.has("nu"))
            {
                params.fail("E", params.label() + " in " + std::to_string(D) + "D needs 'nu'",
                            {"Add e.g. 'nu 0.3;' (Poisson's ratio, in (-1, 0.5))."});
            }
            return fromYoung(params.real("E"), params.real("nu"));
        }
    }
};

} // namespace sph
