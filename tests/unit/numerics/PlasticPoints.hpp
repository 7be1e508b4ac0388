#pragma once
// Random plastic material points for the tests of the return map (ReturnLanesTest,
// TensorLawTest): random committed states, random F around a centre (or uniaxial stretches of
// virgin points, whose be has a double eigenvalue in 3D), a body whose particles hold them, and
// the comparison of a material's two forms of the logarithmic law on such points.
#include "numerics/NumericsSupport.hpp"

#include "materials/plasticity/PlasticHistory.hpp"

#include <cstring>

namespace sph::test
{
// A random plastic state: Cp⁻¹ = Fp⁻¹ Fp⁻ᵀ of a random Fp near I, zz and α.
template <int D>
PlasticState<D> randomState(std::mt19937& random, double amplitude)
{
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Mat<D> Fp = Mat<D>::Identity();
    for (int i = 0; i < D; ++i)
    {
        for (int j = 0; j < D; ++j)
        {
            Fp(i, j) += amplitude * uniform(random);
        }
    }
    const Mat<D> inverse = Fp.inverse();
    const Mat<D> Cp = inverse * inverse.transpose();
    PlasticState<D> s;
    s.inversePlastic = 0.5 * (Cp + Cp.transpose());
    s.inversePlasticZZ = D == 2 ? 1.0 + amplitude * uniform(random) : 1.0;
    s.alpha = uniform(random) > 0.0 ? amplitude * (1.0 + uniform(random)) : 0.0;
    return s;
}

// Makes a packed state particle a's committed one (the restart fields of PlasticHistory).
template <int D>
void setCommitted(ParticleFields<D>& fields, std::size_t a, const double* packed)
{
    const auto set = [&](const char* name, const double* values)
    {
        const auto* field = fields.find(name);
        REQUIRE(field != nullptr);
        field->array->set(a, values);
    };
    set("inversePlasticCauchyGreen", packed);
    if constexpr (D == 2)
    {
        set("inversePlasticCauchyGreenZZ", packed + 4);
    }
    set("equivalentPlasticStrain", packed + PlasticState<D>::packedSize - 1);
}

template <class T>
bool sameBits(const T& a, const T& b)
{
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// `count` random F around `centre` (spread `amplitude`) and random committed states (virgin
// ones with uniaxial F, a stretch along a random axis: in 3D be has a double eigenvalue).
template <int D>
struct RandomPoints
{
    std::vector<Mat<D>> F;
    std::vector<double> states; // packed, PlasticState<D>::packedSize each

    RandomPoints(const Mat<D>& centre, double amplitude, std::size_t count, unsigned seed,
                 bool uniaxial)
        : F(count), states(count * PlasticState<D>::packedSize)
    {
        std::mt19937 random(seed);
        std::uniform_real_distribution<double> uniform(-1.0, 1.0);
        for (std::size_t i = 0; i < count; ++i)
        {
            F[i] = centre;
            for (int k = 0; k < D; ++k)
            {
                for (int l = 0; l < D; ++l)
                {
                    F[i](k, l) += amplitude * uniform(random);
                }
            }
            PlasticState<D> state = randomState<D>(random, 0.3 * amplitude);
            if (uniaxial)
            {
                Vec<D> axis = Vec<D>::Zero();
                for (int k = 0; k < D; ++k)
                {
                    axis[k] = uniform(random);
                }
                axis.normalize();
                F[i] = Mat<D>::Identity() + amplitude * (1.0 + uniform(random)) * axis * axis.transpose();
                state = PlasticState<D>{};
            }
            state.pack(&states[i * PlasticState<D>::packedSize]);
        }
    }
};

// A material whose particles i hold the points' committed states.
template <int D>
struct Body
{
    ParticleFields<D> fields;
    std::unique_ptr<Material<D>> material;

    Body(const std::string& text, const RandomPoints<D>& points)
    {
        const std::size_t count = points.F.size();
        fields.setSize(count);
        material = test::build<Material<D>>(text, {&fields, BodyRange{"body", 0, count}, nullptr}, D);
        REQUIRE(material->historyComponents() == PlasticState<D>::packedSize);
        for (std::size_t i = 0; i < count; ++i)
        {
            setCommitted(fields, i, &points.states[i * PlasticState<D>::packedSize]);
        }
    }
};

// The same points through `logarithm series` and `logarithm principalAxes`: as stress samples
// (P, W, the states to commit, the dissipation) and as particles (the wave speed). Returns
// the number of points that flow.
template <int D>
inline std::size_t compareTheForms(const std::string& materialText, const Mat<D>& centre,
                            double amplitude, std::size_t count, unsigned seed,
                            bool uniaxial = false)
{
    constexpr std::size_t stride = PlasticState<D>::packedSize;
    const RandomPoints<D> points(centre, amplitude, count, seed, uniaxial);
    struct Evaluated
    {
        std::vector<Mat<D>> P;
        std::vector<double> psi, next, dissipation, speed;
    };
    const auto evaluate = [&](const std::string& form)
    {
        Body<D> body(materialText + " logarithm " + form + ";", points);
        Evaluated e{std::vector<Mat<D>>(count), std::vector<double>(count),
                    std::vector<double>(count * stride), std::vector<double>(count),
                    std::vector<double>(count)};
        body.material->evaluate(points.F.data(), e.P.data(), e.psi.data(), count,
                                HistoryOf::samples(points.states.data(), stride, e.next.data(),
                                                   e.dissipation.data()));
        for (std::size_t i = 0; i < count; ++i)
        {
            e.speed[i] = body.material->maxWaveSpeed(&points.F[i], 1, i);
        }
        return e;
    };
    const Evaluated series = evaluate("series");
    const Evaluated axes = evaluate("principalAxes");
    // Floors for what is round-off at a cone's apex or in an opened sand (a stress of 1e-13 Pa
    // against none, and the wave speed √(τ/ρ) of that stress): 1e-14 of the stress at a
    // compression of 0.1 %, 1e-7 of its wave speed.
    const Mat<D> compressed = 0.999 * Mat<D>::Identity();
    Body<D> reference(materialText, points);
    const double referenceStress = reference.material->stress(compressed).norm();
    const double referenceSpeed = reference.material->waveSpeed(compressed);
    std::size_t flowing = 0;
    for (std::size_t i = 0; i < count; ++i)
    {
        INFO("point " << i << " of " << count << ": P " << axes.P[i].norm() << " / "
                       << series.P[i].norm() << ", speed " << axes.speed[i] << " / " << series.speed[i]
                       << ", psi " << axes.psi[i] << " / " << series.psi[i]);
        // The tolerance 1e-10: where a sand's return is the small difference of √J2 and η p, both
        // forms' round-off (of order 1e-16 of each) is amplified alike; elsewhere they agree to
        // about 1e-15.
        const double scale = axes.P[i].norm() + 1e-300;
        CHECK((series.P[i] - axes.P[i]).norm() <= 1e-10 * scale + 1e-14 * referenceStress);
        // (Energies at the apex of a cohesionless cone are round-off: 1e-48 J/m³ and the like.)
        CHECK(std::abs(series.psi[i] - axes.psi[i]) <= 1e-10 * std::abs(axes.psi[i]) + 1e-12);
        CHECK(std::abs(series.dissipation[i] - axes.dissipation[i]) <=
              1e-10 * std::abs(axes.dissipation[i]) + 1e-12);
        CHECK(std::abs(series.speed[i] - axes.speed[i]) <= 1e-10 * axes.speed[i] + 1e-7 * referenceSpeed);
        for (std::size_t k = 0; k < stride; ++k)
        {
            const double a = axes.next[i * stride + k], b = series.next[i * stride + k];
            if (k == PlasticState<D>::flowPressureAt)
            {
                CHECK(std::abs(a - b) <= 1e-10 * std::abs(a) + 1e-15 * scale);
            }
            else
            {
                CHECK(std::abs(a - b) <= 1e-12 * (std::abs(a) + 1.0));
            }
        }
        flowing += axes.dissipation[i] != 0.0 ||
                           !std::equal(&axes.next[i * stride], &axes.next[i * stride] + D * D,
                                       &points.states[i * stride])
                       ? 1
                       : 0;
    }
    return flowing;
}

// Materials of the law's tests: a cohesive and a cohesionless Drucker–Prager, the Taylor bar's
// copper.
namespace plasticMaterials
{
inline const std::string dp = "type druckerPrager; E 7.2e6; nu 0.2; rho 2000; frictionAngle 30; "
                       "dilatancyAngle 10; cohesion 1e4;";
inline const std::string sand = "type druckerPrager; E 0.84e6; nu 0.3; rho 2650; frictionAngle 19.8; "
                         "cohesion 0;";
inline const std::string copper = "type j2Plasticity; E 117e9; nu 0.35; rho 8930; yieldStress 400e6; "
                           "hardeningModulus 100e6;";
} // namespace plasticMaterials

} // namespace sph::test
