#pragma once
// Owns the reference configuration and moves it when the formulation says so (spec §4):
//   x^r ← x,  F^r ← F (= f F^r),  V^r ← det(F) V0,  K ← G f^{-1} (schemes that carry it),
//   then neighbours, kernels, corrected gradients and the scheme's own data are rebuilt.

#include "core/RunScalars.hpp"
#include "formulations/Formulation.hpp"
#include "particles/ParticleFields.hpp"
#include "particles/Parallel.hpp"
#include "stabilisation/Stabilisation.hpp"

#include <algorithm>
#include <functional>

namespace sph
{

template <int D>
class ReferenceManager
{
public:
    // materials: by body, for a scheme that carries the materials' history across a move.
    ReferenceManager(const Formulation<D>& formulation, Stabilisation<D>& scheme,
                     const Kernel& kernel, std::vector<Material<D>*> materials = {})
        : formulation_(formulation), scheme_(scheme), kernel_(kernel),
          materials_(std::move(materials))
    {
    }

    ReferenceConfiguration<D>& reference() { return ref_; }
    const ReferenceConfiguration<D>& reference() const { return ref_; }
    // K is only needed when the scheme uses it and the reference moves (TL: K = 0 always).
    bool carriesK() const
    {
        return scheme_.referenceNeeds(kernel_).gradientOfF && formulation_.updatesReference();
    }

    // x^r = X, V^r = V0, F^r = I; builds everything. `status` names a singular particle.
    ForceStatus initialise(const ParticleSet<D>& particles)
    {
        setInitial(particles);
        return rebuild(particles.body);
    }
    // x^r = X, V^r = V0, F^r = I only: what depends on the neighbours is built later
    // (restored(), or initialise() again), once the particles are known.
    void setInitial(const ParticleSet<D>& particles)
    {
        ref_.setInitial(particles, carriesK());
        ref_.updateStep = 0;
    }

    // A moving reference is part of the restart state (a fixed one is rebuilt from X).
    void declareFields(ParticleFields<D>& fields, RunScalars& scalars)
    {
        if (!formulation_.updatesReference())
        {
            return;
        }
        fields.bind(FieldSpec::vector("referencePosition", "x^r, positions of the reference "
                                                           "configuration [m]")
                        .restart(),
                    ref_.x);
        fields.bind(FieldSpec::scalar("referenceVolume", "V^r = det(F^r) V0 [m^D]").restart(),
                    ref_.V);
        fields.bind(FieldSpec::tensor("referenceDeformationGradient",
                                      "F^r, the deformation gradient of x^r")
                        .restart(),
                    ref_.F, Mat<D>::Identity());
        if (carriesK())
        {
            fields.bind(FieldSpec::thirdOrderTensor("referenceGradientOfF",
                                                    "K = dF^r/dx^r (spec §6.5), K_ijk")
                            .restart(),
                        ref_.K);
        }
        scalars.bind("referenceUpdateStep", ref_.updateStep);
        if (formulation_.movesByStrain())
        {
            scalars.bind("referenceStrain", strainSinceMove_);
        }
        for (const char* name : {"referencePosition", "referenceVolume",
                                 "referenceDeformationGradient", "referenceGradientOfF"})
        {
            if (fields.find(name))
            {
                fieldNames_.emplace_back(name);
            }
        }
    }

    // The fields declareFields() declared: what a moved reference changed.
    const std::vector<std::string>& fieldNames() const { return fieldNames_; }

    // After a restart has read the declared fields back: rebuilds what depends on them.
    ForceStatus restored(const ParticleSet<D>& particles) { return rebuild(particles.body); }

    // What a distributed run does in the middle of a move (both collective, so every rank
    // calls them at the same point, whatever its own particles did).
    struct MoveHooks
    {
        // Sees the status of the new F^r before anything is set (it may stop the run).
        std::function<void(const ForceStatus&)> checked;
        // Once x^r, V^r, F^r (and K) are set, before what depends on them is rebuilt.
        std::function<void()> settled;
    };

    // The moves made by this run (since it started or restarted).
    long moves() const { return moves_; }

    // Whether the reference moves at this step (updateIfDue() will move it).
    bool moveDue(long step) const
    {
        return formulation_.updateDue(step, ref_.updateStep, strainSinceMove_);
    }

    // A new level begins (not the first of a run): the strain measured at the last one is what
    // decides this one's move. (The first level of a restarted run keeps the value it was
    // decided with, which the restart restored: its move, if any, was already made.)
    void beginLevel() { strainSinceMove_ = measuredStrain_; }

    // The strain of the motion since the last move, max_a ‖½(f_aᵀ f_a − I)‖ (Frobenius),
    // f_a = F_a F^r_a⁻¹, from the level's F (a formulation that moves by strain reads it at the
    // next level). `owned`: the particles that count (null: all); `maximum`: over the ranks.
    void measureStrain(const std::vector<Mat<D>>& F, const std::vector<std::uint8_t>* owned,
                       const std::function<double(double)>& maximum = {})
    {
        if (!formulation_.movesByStrain())
        {
            return;
        }
        const std::size_t n = F.size();
        double largest = 0.0;
#pragma omp parallel for schedule(static) reduction(max : largest) if (useThreads(n))
        for (std::size_t a = 0; a < n; ++a)
        {
            if (owned && !(*owned)[a])
            {
                continue;
            }
            const Mat<D> f = F[a] * ref_.F[a].inverse();
            const Mat<D> E = 0.5 * (f.transpose() * f - Mat<D>::Identity());
            largest = std::max(largest, E.norm());
        }
        measuredStrain_ = maximum ? maximum(largest) : largest;
    }

    // Moves the reference configuration to the current positions when due. Returns whether it
    // moved; a failure (det F <= 0 at the move) is reported in `status`.
    bool updateIfDue(long step, const ParticleSet<D>& particles, ForceStatus& status,
                     const MoveHooks& hooks = {})
    {
        if (!moveDue(step))
        {
            return false;
        }
        // F^r and K in place: a scheme reads only particle a's own F^r_a and K_a where it
        // writes its new ones (no second copy: 288 B per particle in 3D). A failed move
        // leaves them changed, but the run then stops, and its last good state is written
        // as not restartable.
        scheme_.moveHistory(particles.x, ref_, particles.body, materials_);
        status = scheme_.referenceUpdate(particles.x, ref_, ref_.F, carriesK() ? &ref_.K : nullptr);
        if (hooks.checked)
        {
            hooks.checked(status);
        }
        if (!status.ok())
        {
            return false;
        }
        ref_.x = particles.x;
        const std::size_t n = ref_.F.size();
#pragma omp parallel for schedule(static) if (useThreads(n))
        for (std::size_t a = 0; a < n; ++a)
        {
            ref_.V[a] = particles.V0[a] * ref_.F[a].determinant();
        }
        ref_.updateStep = step;
        ++moves_;
        if (hooks.settled)
        {
            hooks.settled();
        }
        status = rebuild(particles.body);
        return true;
    }

private:
    // A singular neighbourhood is an input error in the initial configuration (an isolated
    // particle, a body thinner than the kernel can see: setup reports it). Once the reference
    // has moved it is the material's doing (a particle that separated, a layer one particle
    // thick) and the corrected gradients are regularised there (particles/CorrectedGradient.hpp).
    ForceStatus rebuild(const std::vector<int>& body)
    {
        const bool moved = ref_.updateStep > 0;
        const ReferenceNeeds needs = scheme_.referenceNeeds(kernel_);
        ref_.recomputeKernelValues = formulation_.recomputesKernelValues();
        const long bad = ref_.rebuild(kernel_, body, needs.searchRadius,
                                      formulation_.updatesReference(), needs.kernelValues);
        if (bad >= 0 && !moved)
        {
            return ForceStatus::failed(FailureKind::singularReference, bad, 0.0,
                                       "corrected-gradient matrix M (too few neighbours in x^r)");
        }
        const ForceStatus status = scheme_.prepare(ref_);
        if (moved && !status.ok() && status.failure == FailureKind::singularReference)
        {
            return {};
        }
        return status;
    }

    const Formulation<D>& formulation_;
    Stabilisation<D>& scheme_;
    const Kernel& kernel_;
    ReferenceConfiguration<D> ref_;
    std::vector<Material<D>*> materials_;
    std::vector<std::string> fieldNames_;
    // The strain that decides this level's move (restart data) and the one measured at it.
    double strainSinceMove_ = 0.0;
    double measuredStrain_ = 0.0;
    long moves_ = 0;
};

} // namespace sph
