#pragma once
// Internal-force schemes ("stabilisation" in system/sphSchemes), runtime-selectable:
//
//   stabilisation { type gradF; }        // the types: sphSolid -listTypes stabilisation
//
// Every scheme works with both formulations (total- and updated-Lagrangian, which differ only
// in the reference configuration it is given) and in 1D/2D/3D. Each has an energy and a force:
// the force is -∂Π/∂x of the scheme's discrete energy Π (spec §3, §4, §5.1, §6), except
// hourglass control, whose pair forces are not derived from an energy (spec §12).
//
// Forces are computed in gather form (each particle sums what acts on it), so the result does
// not depend on the number of threads.

#include "core/Registry.hpp"
#include "kernels/Kernel.hpp"
#include "materials/Material.hpp"
#include "particles/Parallel.hpp"
#include "particles/ParticleFields.hpp"
#include "particles/ReferenceConfiguration.hpp"

#include <string>
#include <vector>

namespace sph
{

// What a force evaluation reads.
template <int D>
struct ForceInput
{
    const std::vector<Vec<D>>& x;                      // current positions
    const std::vector<double>& V0;                     // initial volumes
    const std::vector<int>& body;                      // body of each particle
    const std::vector<BodyRange>& bodies;              // contiguous particle ranges
    const std::vector<const Material<D>*>& materials;  // by body
    const ReferenceConfiguration<D>& ref;
    // x is the reference configuration itself (bitwise; the reference was set from these
    // positions this step), so f = I and ∇f = 0 exactly and need not be computed.
    bool atReference = false;
    // A distributed run's owned particles (1) and ghosts (0). Only owned particles count in the
    // strain energy and the failure checks: a ghost's neighbourhood is cut at the edge of the
    // ghost layer, and its owner checks it. Null: every particle counts (a serial run).
    const std::vector<std::uint8_t>* owned = nullptr;
    // A distributed run's global index of each local particle (null: the index), for what a
    // scheme keeps by particle across changes of the local particles (gradF's sample history).
    const std::vector<int>* globalId = nullptr;
    bool counts(std::size_t a) const { return !owned || (*owned)[a] != 0; }
};

// What a force evaluation writes.
template <int D>
struct ForceOutput
{
    std::vector<Vec<D>>& T; // internal force on each particle
    std::vector<Mat<D>>& F; // deformation gradient F = f F^r
    std::vector<Mat<D>>& P; // first Piola-Kirchhoff stress at F
};

// What committing the materials' history reads: the last force evaluation's F (the accepted
// level) and the materials that keep a history, by body (null for the others).
template <int D>
struct HistoryCommit
{
    const std::vector<Mat<D>>& F;
    const std::vector<double>& V0;
    const std::vector<BodyRange>& bodies;
    const std::vector<Material<D>*>& materials;
    // A distributed run's owned particles (null: all). Every local particle commits (a ghost's
    // history must stay its owner's: its stress is read within the next force evaluation), but
    // only owned particles count in the dissipated energy.
    const std::vector<std::uint8_t>* owned = nullptr;
};

// Each particle's state committed at its own F, in chunks in parallel; returns the dissipated
// energy, summed in chunk order (independent of the thread count).
template <int D>
double commitParticleHistory(const HistoryCommit<D>& in)
{
    const std::size_t chunk = 256;
    double total = 0.0;
    for (std::size_t b = 0; b < in.bodies.size(); ++b)
    {
        Material<D>* material = in.materials[b];
        if (!material)
        {
            continue;
        }
        // Chunks of at most `chunk` particles, none mixing owned particles and ghosts.
        const BodyRange& range = in.bodies[b];
        std::vector<std::pair<std::size_t, std::size_t>> chunks;
        for (std::size_t first = range.begin; first < range.end;)
        {
            std::size_t last = std::min(range.end, first + chunk);
            if (in.owned)
            {
                last = static_cast<std::size_t>(
                    std::find_if(in.owned->begin() + static_cast<long>(first) + 1,
                                 in.owned->begin() + static_cast<long>(last),
                                 [&](std::uint8_t flag) { return flag != (*in.owned)[first]; }) -
                    in.owned->begin());
            }
            chunks.emplace_back(first, last);
            first = last;
        }
        std::vector<double> dissipated(chunks.size(), 0.0);
#pragma omp parallel for schedule(static) if (useThreads(range.size()))
        for (std::size_t i = 0; i < chunks.size(); ++i)
        {
            const auto [first, last] = chunks[i];
            dissipated[i] = material->commit(&in.F[first], &in.V0[first], first, last - first);
        }
        for (std::size_t i = 0; i < chunks.size(); ++i)
        {
            if (!in.owned || (*in.owned)[chunks[i].first])
            {
                total += dissipated[i];
            }
        }
    }
    return total;
}

// Why a state cannot be used. The solver words its diagnosis by the kind; the message is the
// scheme's own description of the quantity (e.g. which matrix is singular).
enum class FailureKind
{
    none,
    nonPositiveJacobian, // det F <= 0 or not finite (value: det F)
    nonFiniteForce,      // (value: |T|)
    singularReference,   // a matrix built from a reference neighbourhood is singular
    timeStepCollapse,    // (value: the step)
    particleCrossing     // 1D: a particle passed its neighbour
};

// A force evaluation's energy and, if the state is unusable, the first bad particle.
struct ForceStatus
{
    double strainEnergy = 0.0; // Π, when asked for
    long badParticle = -1;     // the first bad particle
    double badValue = 0.0;     // the value that made it bad (see FailureKind)
    FailureKind failure = FailureKind::none;
    std::string message;       // what is bad: "det F", "least-squares matrix Z (...)", ...
    bool ok() const { return failure == FailureKind::none; }

    static ForceStatus failed(FailureKind kind, long particle, double value, std::string message)
    {
        ForceStatus status;
        status.failure = kind;
        status.badParticle = particle;
        status.badValue = value;
        status.message = std::move(message);
        return status;
    }
};

// What a scheme needs the reference configuration to carry.
struct ReferenceNeeds
{
    double searchRadius = 0.0;  // of the neighbour search (the kernel support unless more)
    bool gradientOfF = false;   // K = ∂F^r/∂x^r (the gradient-of-F scheme)
    bool kernelValues = false;  // W_ab per pair (the gradients are always there); a scheme
                                // that does not read them does not pay for storing them
};

template <int D>
class Stabilisation : public RegisteredModel
{
public:
    static constexpr const char* family = "stabilisation";
    static constexpr int dimension = D;
    struct Args
    {
        const Kernel* kernel = nullptr;
        ParticleFields<D>* fields = nullptr; // for a scheme's own per-particle fields
        // The formulation moves the reference configuration (updated Lagrangian); false: total
        // Lagrangian (gradF's elasticState samples then move frames of their own, §G25).
        bool referenceMoves = true;
    };

    virtual ~Stabilisation() = default;

    virtual ReferenceNeeds referenceNeeds(const Kernel& kernel) const
    {
        return {kernel.supportRadius(), false, false};
    }
    // Precomputes what depends only on the reference configuration; called after every rebuild.
    // A singular neighbourhood is a singularReference failure whose message names the matrix.
    virtual ForceStatus prepare(const ReferenceConfiguration<D>& ref) = 0;

    // F = f F^r at positions x (for moving the reference configuration to x). Schemes that
    // carry K also return the new K = G f^{-1} (spec §6.5) in newK. F and newK may be the
    // reference's own F^r and K (the move updates them in place): F_a and K_a may be computed
    // from particle a's own F^r_a and K_a only, never from a neighbour's.
    virtual ForceStatus referenceUpdate(const std::vector<Vec<D>>& x,
                                        const ReferenceConfiguration<D>& ref,
                                        std::vector<Mat<D>>& F,
                                        std::vector<Tensor3<D>>* newK) const = 0;

    // Called just before referenceUpdate() moves the reference to x, with the old reference
    // still in place: a scheme that keeps history per pair carries it across the move here,
    // with the materials by body (gradF's elasticState samples, docs/theory/gradF-plastic.md
    // §G4). By default nothing.
    virtual void moveHistory(const std::vector<Vec<D>>& x, const ReferenceConfiguration<D>& ref,
                             const std::vector<int>& body,
                             const std::vector<Material<D>*>& materials)
    {
        (void)x;
        (void)ref;
        (void)body;
        (void)materials;
    }

    // Whether moveHistory() can dissipate energy (gradF's openedSamples particle,
    // docs/theory/gradF-plastic.md (G22.2)), and how much the last one did over the particles
    // `owned` names (null: all). By default it cannot.
    virtual bool movesDissipate() const { return false; }
    virtual double moveDissipation(const std::vector<std::uint8_t>* owned) const
    {
        (void)owned;
        return 0.0;
    }

    // Whether moveHistory() changes the materials' own (per-particle) history.
    virtual bool movesParticleHistory() const { return false; }

    // Whether the scheme's own force vanishes wherever the positions are the reference's
    // (hourglass control measures the deviation from the affine map since the last move): with
    // the reference moved before every evaluation it then never acts, though perturbed
    // positions feel it (stepBound operator refuses that, docs/theory/timeStep.md §T4).
    virtual bool vanishesAtReference() const { return false; }

    // What to try next when a run with this scheme fails (the solver's diagnosis): a scheme
    // that cannot help itself names another; `updated`: the reference moves, `plastic`: some
    // material keeps a plastic history.
    virtual std::string nextToTry(bool updated, bool plastic) const
    {
        (void)plastic;
        return updated ? "stabilisation gradF, or formulation totalLagrangian"
                       : "stabilisation gradF";
    }

    // F_a = f_a F^r_a of one particle at positions x, as the force evaluation at x computes it
    // (to round-off; contact needs the current volumes V0 det F of the few particles near another body).
    virtual Mat<D> deformationGradient(std::size_t a, const std::vector<Vec<D>>& x,
                                       const ReferenceConfiguration<D>& ref) const = 0;

    // Internal forces, F and P at the current positions; the energy Π when wantEnergy.
    virtual ForceStatus computeForces(const ForceInput<D>& in, ForceOutput<D>& out,
                                      bool wantEnergy) = 0;

    // Π at the current positions (the energy the force derives from).
    virtual double energy(const ForceInput<D>& in) = 0;

    // The operator probe (docs/theory/timeStep.md §T3) evaluates the forces at perturbed
    // positions between a level's evaluation and its commit. A scheme whose evaluation leaves
    // for the commit nothing but F, P and the forces (which the solver keeps) and what it can
    // set aside here returns true, and gets it back from restoreEvaluation() after the probe;
    // otherwise (false, the default) the solver evaluates the level once more.
    virtual bool setAsideEvaluation() { return false; }
    virtual void restoreEvaluation() {}

    // Whether the scheme evaluates the materials at the particles' own F and committed history
    // (HistoryOf::particles): a plastic material then remembers each particle's return for the
    // time step and the commit (ReturnMemo). gradF evaluates its stress samples instead.
    virtual bool evaluatesParticles() const { return true; }

    // Materials with history (docs/theory/plasticity.md §P7). A scheme that keeps history of
    // its own declares it here as particle fields (called once, when some material has
    // history), so that it is restart data and moves with its particles between ranks...
    virtual void declareHistory(const std::vector<const Material<D>*>& materials,
                                ParticleFields<D>& fields)
    {
        (void)materials;
        (void)fields;
    }
    // ...and commits the history at the state of the last force evaluation, once per accepted
    // level, returning the dissipated energy. By default each particle at its own F.
    virtual double commitHistory(const HistoryCommit<D>& in) { return commitParticleHistory(in); }
};

} // namespace sph
