#pragma once
// Artificial viscosity (system/sphSchemes), runtime-selectable:
//
//   artificialViscosity { type none; }                          // the default when absent
//   artificialViscosity { type monaghan; alpha 1; beta 2; }     // sphSolid -listTypes ...
//
// A pair force that damps compression between neighbouring particles of the same body (shocks,
// impacts), added to a^n in the solver's `applyViscosity` phase. It is evaluated before the
// time step is chosen (it reads x^n, v^{n-1/2} and F^n only), so the step can account for it
// (signalSpeed) and a restart recomputes it bit-identically from the state file.
// `none` costs nothing: the solver skips it entirely.

#include "core/Registry.hpp"
#include "kernels/Kernel.hpp"
#include "materials/Material.hpp"
#include "particles/ParticleRanks.hpp"
#include "particles/ParticleSet.hpp"

#include <vector>

namespace sph
{

// What a viscosity reads at level n.
template <int D>
struct ViscosityState
{
    const std::vector<Vec<D>>& x;    // x^n
    const std::vector<Vec<D>>& v;    // the velocity the integrator holds (v^{n-1/2})
    const ParticleSet<D>& particles; // masses, bodies, fixed flags, F^n (ρ = ρ0 / det F)
    // A distributed run (null: serial): the rank's ghosts reach one reach() in x^n, with the
    // owners' x, v and F; a model computes the owned particles' accelerations and agrees with
    // the other ranks on what bounds the time step.
    const ParticleRanks* ranks = nullptr;
};

template <int D>
class ArtificialViscosity : public RegisteredModel
{
public:
    static constexpr const char* family = "artificialViscosity";
    static constexpr int dimension = D;
    struct Args
    {
        const Kernel* kernel = nullptr;
        std::vector<const Material<D>*> materials; // by body: ρ0 and c0 = c(F = I)
    };

    virtual ~ArtificialViscosity() = default;

    // False when the model never acts (`none`): the solver then skips it entirely.
    virtual bool active() const = 0;
    // The viscous accelerations at level n into `acceleration` (resized; zero for fixed
    // particles).
    virtual void compute(const ViscosityState<D>& state, std::vector<Vec<D>>& acceleration) = 0;
    // The speed that bounds the time step, Δt = courant h / signalSpeed(c_max), given the
    // largest wave speed of the materials (after compute()).
    virtual double signalSpeed(double waveSpeed) const { return waveSpeed; }
    // How far from a particle, in the current configuration, it reads other particles.
    virtual double reach() const { return 0.0; }
    // The local particles changed (a distributed run gathered new ghosts): forget anything
    // kept per particle between calls.
    virtual void particlesChanged() {}
};

} // namespace sph
