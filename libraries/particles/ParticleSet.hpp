#pragma once
// Particle storage as a structure of arrays: one contiguous array per field, so the hot loops
// stream only the fields they use.

#include "particles/Types.hpp"

#include <string>
#include <vector>

namespace sph
{

// A body: a named, contiguous range of particles with one material.
struct BodyRange
{
    std::string name;
    std::size_t begin = 0;
    std::size_t end = 0;
    std::size_t size() const { return end - begin; }
};

template <int D>
struct ParticleSet
{
    std::vector<Vec<D>> x;  // current position x^n
    std::vector<Vec<D>> v;  // velocity: v^0 before the first step, then the half step v^{n-1/2}
    std::vector<Vec<D>> X;  // initial position
    std::vector<double> V0; // initial volume
    std::vector<double> m;  // mass = rho0 V0
    std::vector<int> body;  // index into `bodies`
    std::vector<std::uint8_t> fixed; // 1: position held, force discarded
    std::vector<Mat<D>> F;  // deformation gradient of the last force evaluation
    std::vector<Mat<D>> P;  // first Piola-Kirchhoff stress of the last force evaluation
    std::vector<BodyRange> bodies;

    std::size_t size() const { return x.size(); }

    void resize(std::size_t n)
    {
        x.resize(n, Vec<D>::Zero());
        v.resize(n, Vec<D>::Zero());
        X.resize(n, Vec<D>::Zero());
        V0.resize(n, 0.0);
        m.resize(n, 0.0);
        body.resize(n, 0);
        fixed.resize(n, 0);
        F.resize(n, Mat<D>::Identity());
        P.resize(n, Mat<D>::Zero());
    }
};

} // namespace sph
