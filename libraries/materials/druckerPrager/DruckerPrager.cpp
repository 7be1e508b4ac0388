#include "materials/druckerPrager/DruckerPrager.hpp"

#include "core/Format.hpp"

#include <numbers>

namespace sph
{

ConeMatching::Kind ConeMatching::parse(const std::string& name)
{
    // The schema's choices admit only these words.
    return name == "outer"             ? Kind::outer
           : name == "inner"           ? Kind::inner
           : name == "planeStrainFlow" ? Kind::planeStrainFlow
                                       : Kind::planeStrain;
}

namespace
{
// Bui et al. 2008: 3 tan a/√(9 + 12 tan² a) = sin a/√(1 + sin² a/3), and ξ likewise.
double planeStrainEta(double angle)
{
    const double t = std::tan(angle);
    return 3.0 * t / std::sqrt(9.0 + 12.0 * t * t);
}
double planeStrainXi(double angle)
{
    const double t = std::tan(angle);
    return 3.0 / std::sqrt(9.0 + 12.0 * t * t);
}
} // namespace

double ConeMatching::apexPressure(Kind kind, double phi, double psi, double cohesion)
{
    const Cone cone = of(kind, phi, psi);
    return cone.xi * cohesion / cone.eta;
}

ConeMatching::Cone ConeMatching::of(Kind kind, double phi, double psi)
{
    switch (kind)
    {
    case Kind::planeStrain:
        return {planeStrainEta(phi), planeStrainXi(phi), planeStrainEta(psi)};
    case Kind::planeStrainFlow:
    {
        // (P9.6): steady plane-strain flow on the cone of η̄ has σzz − p = −(2η̄/3)√J2, so
        // √J2 = t/c with c = √(1 − η̄²/3), t the in-plane Mohr radius, and Φ = 0 reads
        // t (1 − η η̄/3)/c + η m = ξ c0 (m the in-plane mean stress): Mohr–Coulomb of angle φ.
        const double etaBar = planeStrainEta(psi);
        const double c = std::sqrt(1.0 - etaBar * etaBar / 3.0);
        const double eta = std::sin(phi) / (c + etaBar * std::sin(phi) / 3.0);
        return {eta, std::cos(phi) * (1.0 - eta * etaBar / 3.0) / c, etaBar};
    }
    case Kind::outer:
    case Kind::inner:
    default:
    {
        const double sign = kind == Kind::outer ? -1.0 : 1.0; // 3 ∓ sin a
        const auto through = [sign](double angle, double trig)
        { return 6.0 * trig / (std::sqrt(3.0) * (3.0 + sign * std::sin(angle))); };
        return {through(phi, std::sin(phi)), through(phi, std::cos(phi)),
                through(psi, std::sin(psi))};
    }
    }
}

template <int D> std::string DruckerPrager<D>::description()
{
    return "Finite-strain Drucker-Prager plasticity (friction, cohesion, dilatancy, tension "
           "cut-off), perfectly plastic: F = Fe Fp, Hencky elasticity, cone/apex return on the "
           "log strain (without principal axes: in 3D by its series where the elastic strain is "
           "small, in 2D in closed form; key logarithm, §P12-§P13; docs/theory/plasticity.md "
           "§P9); 2D plane strain and 3D.";
}

template <int D> Schema DruckerPrager<D>::schema()
{
    return Material<D>::commonSchema()
        .include(IsotropicElasticity::schema())
        .include(ReturnMapPlasticity<D, DruckerPrager<D>>::lawSchema())
        .add(Key::real("frictionAngle", "internal friction angle phi [degrees] (a "
                                        "pressure-independent material, phi = 0, is "
                                        "j2Plasticity)")
                 .range(0.0, 90.0, false, false))
        .add(Key::real("cohesion", "cohesion c [Pa]").nonNegative().defaultValue("0"))
        .add(Key::real("dilatancyAngle", "dilatancy angle psi [degrees], at most frictionAngle; "
                                         "0: no plastic volume change, = phi: associative")
                 .range(0.0, 90.0, true, false)
                 .defaultValue("0"))
        .add(Key::real("tensileStrength", "tension cut-off sigmaT [Pa]: the largest pressure "
                                          "tr(tau)/3; at most (and by default) the cone's apex "
                                          "pressure xi c/eta")
                 .nonNegative()
                 .optional())
        .add(Key::word("coneMatching", "which Mohr-Coulomb the cone matches: planeStrain (Bui "
                                       "et al. 2008; exact in plane-strain flow when psi = "
                                       "phi), planeStrainFlow (exact in plane-strain flow at "
                                       "any psi), outer (triaxial compression), inner "
                                       "(triaxial extension)")
                 .choices(ConeMatching::names())
                 .defaultValue("planeStrain"))
        .add(Key::real("strengthReduction",
                       "strength reduction factor F (slope safety, docs/theory/geotechnics.md "
                       "§E2): the material has cohesion c/F, friction angle atan(tan(phi)/F), "
                       "dilatancy at most that angle and tensileStrength/F; its elasticity is "
                       "unchanged, its at-rest K0 is 1 - sin of the reduced angle")
                 .positive()
                 .defaultValue("1"));
}

ReducedStrength ReducedStrength::of(double phi, double psi, double cohesion, double factor)
{
    ReducedStrength r;
    r.frictionAngle = std::atan(std::tan(phi) / factor);
    r.dilatancyAngle = std::min(psi, r.frictionAngle);
    r.cohesion = cohesion / factor;
    return r;
}

template <int D>
DruckerPrager<D>::DruckerPrager(const Params& params, const typename Material<D>::Args& args)
    : ReturnMapPlasticity<D, DruckerPrager<D>>(params, args)
{
    const double degree = std::numbers::pi / 180.0;
    const double phi = params.real("frictionAngle");
    const double psi = params.real("dilatancyAngle");
    const double reduction = params.real("strengthReduction");
    if (psi > phi)
    {
        params.fail("dilatancyAngle",
                    "druckerPrager: dilatancyAngle " + formatNumber(psi) +
                        " exceeds frictionAngle " + formatNumber(phi) +
                        ": the plastic flow would create energy under high confinement",
                    {"Use a value in [0, " + formatNumber(phi) +
                     "]; 0 (no plastic volume "
                     "change) is usual for soils, " +
                     formatNumber(phi) + " is associative."});
    }
    const ReducedStrength reduced =
        ReducedStrength::of(phi * degree, psi * degree, params.real("cohesion"), reduction);
    // Jaky's K0 of the reduced soil (geotechnics.md §E2): the soil's own can lie outside the
    // reduced cone (φ = 20°, F = 2).
    atRest_ = 1.0 - std::sin(reduced.frictionAngle);
    cohesion_ = reduced.cohesion;
    const ConeMatching::Kind kind = ConeMatching::parse(params.word("coneMatching"));
    const ConeMatching::Cone cone =
        ConeMatching::of(kind, reduced.frictionAngle, reduced.dilatancyAngle);
    eta_ = cone.eta;
    xi_ = cone.xi;
    etaBar_ = cone.etaBar;
    apexPressure_ = xi_ * cohesion_ / eta_;
    // The cut-off is checked as given, against the unreduced cone's apex, then reduced with
    // the strength. Every matching has its apex at ξ c/η = c cot φ, which F does not change
    // (c/F · F cot φ): the reduced cut-off stays below the reduced apex.
    const double givenApex = ConeMatching::apexPressure(kind, phi * degree, psi * degree,
                                                        params.real("cohesion"));
    const double given =
        params.has("tensileStrength") ? params.real("tensileStrength") : givenApex;
    if (given > givenApex)
    {
        params.fail("tensileStrength",
                    "druckerPrager: tensileStrength " + formatNumber(given) +
                        " exceeds the cone's apex pressure xi c/eta = " + formatNumber(givenApex) +
                        ": no stress on the cone has that pressure",
                    {"Use a value in [0, " + formatNumber(givenApex) +
                     "], or leave the key out (the apex)."});
    }
    tensileStrength_ = params.has("tensileStrength") ? given / reduction : apexPressure_;
}

template class DruckerPrager<2>;
template class DruckerPrager<3>;

SPH_REGISTER_DIM_MODEL_FOR(Material, DruckerPrager, "druckerPrager", 2, 3);

} // namespace sph
