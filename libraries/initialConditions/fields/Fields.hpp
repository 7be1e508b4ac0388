#pragma once
// Initial fields of a body, by region, in constant/bodies:
//
//   initialVelocity      { name { region { ... }; type uniform; velocity (1 0); } }
//   initialDisplacement  { name { region { ... }; type random; amplitude 1e-9; } }
//
// Velocity fields: uniform (the default type), rotation, cantileverMode, twist (3D).
// Displacement fields (x = X + u(X) at t = 0): affine, random, checkerboard.
// Both are functions of the initial position X (and the particle's index, for `random`).
// Each type is in its own file: UniformVelocity.cpp, RotationVelocity.cpp, CantileverMode.cpp,
// TwistVelocity.cpp, AffineDisplacement.cpp, RandomDisplacement.cpp, CheckerboardDisplacement.cpp.

#include "core/Registry.hpp"
#include "particles/Types.hpp"

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

} // namespace sph
