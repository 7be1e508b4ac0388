#pragma once
// Contact between bodies (system/sphSchemes):
//
//   contact { type repulsion; ... }      // the types: sphSolid -listTypes contact
//
// Applied after the leapfrog position update as a velocity change (spec §9, §12). A case with
// one body, or with bodies far apart, costs nothing: `none` does no work at all, and models
// only search pairs of bodies whose bounding boxes come within reach.

#include "core/Registry.hpp"
#include "kernels/Kernel.hpp"
#include "particles/ParticleRanks.hpp"
#include "particles/ParticleSet.hpp"

#include <functional>
#include <string>
#include <vector>

namespace sph
{

// What a contact model may read and change after x^{n+1} = x^n + Δt v^{n+1/2}.
template <int D>
struct ContactState
{
    const std::vector<Vec<D>>& x;   // x^{n+1}
    std::vector<Vec<D>>& v;         // v^{n+1/2}, changed in place
    const ParticleSet<D>& particles; // masses, initial volumes, bodies, fixed flags
    double deltaT;
    // J_a = det F_a at x^{n+1} (the current volume is V0 J, spec §9), evaluated by the scheme
    // on demand: contact needs it only for the few particles near another body.
    std::function<double(std::size_t)> jacobian;
    // A distributed run (null: serial). A rank holds ghosts reaching twice reach() in the
    // current configuration; a model agrees with the other ranks on what it sums over whole
    // bodies (bounding boxes), and takes from the owners what only they can compute (J, which
    // reads a ghost's neighbours in the reference configuration).
    const ParticleRanks* ranks = nullptr;
};

template <int D>
class Contact : public RegisteredModel
{
public:
    static constexpr const char* family = "contact";
    static constexpr int dimension = D;
    struct Args
    {
        const Kernel* kernel = nullptr;
        std::vector<std::string> bodyNames; // in body-index order
    };

    virtual ~Contact() = default;

    // False when the model never acts (`none`): the solver then skips it entirely.
    virtual bool active() const = 0;
    // Applies the velocity change; returns the velocity changes Δv (for the work accounting).
    virtual void apply(ContactState<D>& state, std::vector<Vec<D>>& deltaV) = 0;
    // How far from a particle, in the current configuration, the model reads other particles:
    // a distributed run keeps ghosts twice as far (a's change reads its neighbours b, and what
    // b computed from b's own).
    virtual double reach() const { return 0.0; }
    // Pairs of bodies searched in the last call (0 when none could touch).
    virtual std::size_t pairsSearched() const { return 0; }
};

} // namespace sph
