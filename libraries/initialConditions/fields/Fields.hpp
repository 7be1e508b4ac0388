#pragma once
// Initial fields of a body, by region, in constant/bodies:
//
//   initialVelocity      { name { region { ... }; type uniform; velocity (1 0); } }
//   initialDisplacement  { name { region { ... }; type random; amplitude 1e-9; } }
//   initialStress        { type geostatic; K0 0.66; }     (the whole body)
//
// Velocity fields: uniform (the default type), rotation, cantileverMode, twist (3D).
// Displacement fields (x = X + u(X) at t = 0): affine, random, checkerboard.
// Both are functions of the initial position X (and the particle's index, for `random`).
// Stress fields (the Cauchy stress at t = 0, stored by the material as an initial elastic
// strain: Material::startFromStress): geostatic (GeostaticStress.cpp).
// Each type is in its own file: UniformVelocity.cpp, RotationVelocity.cpp, CantileverMode.cpp,
// TwistVelocity.cpp, AffineDisplacement.cpp, RandomDisplacement.cpp, CheckerboardDisplacement.cpp.

#include "core/Registry.hpp"
#include "particles/Types.hpp"

#include <vector>

namespace sph
{

template <int D>
class VelocityField
{
public:
    static constexpr const char* family = "velocityField";
    static constexpr int dimension = D;
    struct Args
    {
    };
    virtual ~VelocityField() = default;
    virtual Vec<D> velocity(const Vec<D>& X) const = 0;
};

template <int D>
class DisplacementField
{
public:
    static constexpr const char* family = "displacementField";
    static constexpr int dimension = D;
    struct Args
    {
    };
    virtual ~DisplacementField() = default;
    // u for the particle with initial position X and index `particle`.
    virtual Vec<D> displacement(const Vec<D>& X, std::size_t particle) const = 0;
};

// The initial stress of one body: what it needs to know of the body and of the case.
template <int D>
class StressField
{
public:
    static constexpr const char* family = "stressField";
    static constexpr int dimension = D;
    struct Args
    {
        Vec<D> gravity = Vec<D>::Zero();
        double density = 0.0;   // ρ0 of the body's material
        double atRest = 0.0;    // the material's K0 (Material::atRestCoefficient; NaN: none)
        const std::vector<Vec<D>>* X = nullptr;   // initial positions of all particles
        const std::vector<double>* V0 = nullptr;  // initial volumes of all particles
        std::size_t begin = 0;  // the body's particles
        std::size_t end = 0;
    };
    virtual ~StressField() = default;
    // The Cauchy stress of the particle (3×3: in 2D zz is the out-of-plane stress).
    virtual Eigen::Matrix3d stress(std::size_t particle) const = 0;
};

} // namespace sph
