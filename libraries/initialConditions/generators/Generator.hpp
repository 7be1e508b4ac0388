#pragma once
// Particle generators: system/particlesDict names one per body,
//
//   bar   { type line; start 0; end 0.1333; n 40; }
//   ringA { type annulus; centre (-0.045 0); innerRadius 0.03; outerRadius 0.04; spacing 1e-3; }
//
// Types: line (1D), box (1D/2D/3D), disk, annulus and polygon (2D), cylinder (3D), vtu (import a point
// set). Lattice shapes are a square/cubic lattice of the given spacing clipped to the shape;
// every particle gets the volume spacing^dim (line: half volumes at the ends by default, so
// the volumes tile the bar exactly).

#include "core/Format.hpp"
#include "core/Registry.hpp"
#include "particles/Types.hpp"

#include <unistd.h>

#include <cmath>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace sph
{

// Refuses (at `key`, with the file:line of the key) a body of `count` particles that a run
// could not hold: more than 2^31 particles, or more memory than this machine has at the few kB
// per particle a run needs (a spacing of 1e-300 made sphParticles spin for ever; issue 31).
// `shape` names the generator, `what` says what made the count ("spacing 1e-9 m makes"),
// `hint` what to change.
inline void checkParticleCount(const Params& p, const std::string& key, const std::string& shape,
                               const std::string& what, double count, const std::string& hint)
{
    const double bytesPerParticle = 4096.0; // a 3D updated-Lagrangian gradF run: ~3.6 kB
    const double pages = static_cast<double>(sysconf(_SC_PHYS_PAGES));
    const double memory = pages * static_cast<double>(sysconf(_SC_PAGE_SIZE));
    if (!(count <= 2147483647.0) || !(count * bytesPerParticle <= memory))
    {
        p.fail(key,
               shape + ": " + what + " about " + formatScientific(count) +
                   " particles, which need about " +
                   formatScientific(count * bytesPerParticle / 1073741824.0) +
                   " GiB to run (this machine has " + formatNumber(memory / 1073741824.0) +
                   " GiB)",
               {hint});
    }
}

// checkParticleCount for a lattice of `spacing` over a bounding box of `extent`, at `spacing`.
template <int D>
void checkLatticeSize(const Params& p, const std::string& shape, const Vec<D>& extent,
                      double spacing)
{
    double count = 1.0;
    for (int d = 0; d < D; ++d)
    {
        count *= std::floor(std::abs(extent[d]) / spacing) + 1.0;
    }
    checkParticleCount(p, "spacing", shape, "spacing " + formatNumber(spacing) + " m makes",
                       count,
                       "Choose a larger spacing: the particle count grows as (size / spacing)^" +
                           std::to_string(D) + ".");
}

template <int D>
struct GeneratedBody
{
    std::vector<Vec<D>> X;
    std::vector<double> V;
    double spacing = 0.0;
};

template <int D>
class Generator
{
public:
    static constexpr const char* family = "generator";
    static constexpr int dimension = D;
    struct Args
    {
        std::filesystem::path caseDir; // for files named relative to the case
    };

    virtual ~Generator() = default;
    virtual GeneratedBody<D> generate() const = 0;
};

// The lattice points origin + spacing·(i, j, k) inside the box [lower, upper] for which
// `inside` holds, in lexicographic order (x fastest), each with volume spacing^D.
template <int D>
GeneratedBody<D> clippedLattice(const Vec<D>& origin, double spacing, const Vec<D>& lower,
                                const Vec<D>& upper,
                                const std::function<bool(const Vec<D>&)>& inside)
{
    GeneratedBody<D> body;
    body.spacing = spacing;
    std::array<long, D> first{};
    std::array<long, D> last{};
    for (int d = 0; d < D; ++d)
    {
        first[d] = static_cast<long>(std::floor((lower[d] - origin[d]) / spacing)) - 1;
        last[d] = static_cast<long>(std::ceil((upper[d] - origin[d]) / spacing)) + 1;
    }
    std::array<long, D> index = first;
    const double volume = std::pow(spacing, D);
    while (true)
    {
        Vec<D> p;
        for (int d = 0; d < D; ++d)
        {
            p[d] = origin[d] + spacing * static_cast<double>(index[d]);
        }
        if (inside(p))
        {
            body.X.push_back(p);
            body.V.push_back(volume);
        }
        int d = 0;
        while (d < D && index[d] == last[d])
        {
            index[d] = first[d];
            ++d;
        }
        if (d == D)
        {
            break;
        }
        ++index[d];
    }
    return body;
}

// The lattice through `centre` clipped to inner <= |x - centre| <= outer (a disk for inner < 0).
// A small tolerance keeps lattice points that sit exactly on a radius.
template <int D>
GeneratedBody<D> latticeInAnnulus(const Vec<D>& centre, double inner, double outer, double spacing)
{
    const double tolerance = 1e-9 * spacing;
    return clippedLattice<D>(centre, spacing, centre - Vec<D>::Constant(outer),
                             centre + Vec<D>::Constant(outer), [&](const Vec<D>& x) {
                                 const double r = (x - centre).norm();
                                 return r >= inner - tolerance && r <= outer + tolerance;
                             });
}

} // namespace sph
