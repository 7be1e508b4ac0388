#pragma once
// Random plastic material points for the tests of the return map (ReturnLanesTest,
// TensorLawTest): random committed states, random F around a centre (or uniaxial stretches of
// virgin points, whose be has a double eigenvalue in 3D), and a body whose particles hold them.
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

} // namespace sph::test
