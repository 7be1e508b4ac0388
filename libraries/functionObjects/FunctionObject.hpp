#pragma once
// Function objects: per-run diagnostics named in system/controlDict,
//
//   functions
//   {
//       freeEnd { type probes; points ((0.1333)); fields (displacement velocity); }
//       energy  { type energy; }
//   }
//
// each writing postProcessing/<name>/<name>.dat: whitespace-separated columns, one '#' header
// line of column names, first column `time` (gnuplot-ready).
//
// Keys common to every function object:
//   writeInterval | time between rows [s]; 0 writes every step | 0

#include "core/Registry.hpp"
#include "kernels/Kernel.hpp"
#include "materials/Material.hpp"
#include "particles/ParticleFields.hpp"
#include "particles/ParticleRanks.hpp"
#include "particles/ReferenceConfiguration.hpp"

#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace sph
{

// The energy balance at a time level (spec §10), kept by the solver's energy audit:
//   total = kinetic + strain + wallPotential + dissipated + damped - external - contact
//           - wallWork - viscousWork,
//   conserved by an exact integrator;
//   drift = (total - total at the first level) / |total at the first level|.
struct EnergyBalance
{
    double kinetic = 0.0;  // Σ ½ m |v^n|^2
    double strain = 0.0;   // Π^n of the scheme
    double external = 0.0; // work of external (body) forces since t = 0
    double contact = 0.0;  // work of contact forces since t = 0
    double dissipated = 0.0; // energy dissipated by plastic flow since t = 0 (committed levels)
    double wallPotential = 0.0; // Σ ½ k δ² of the rigid walls (walls/WallSet.hpp)
    double wallWork = 0.0; // work of the walls since t = 0: moving, removing, friction
    double viscousWork = 0.0; // work of the artificial viscosity since t = 0 (<= 0: dissipated)
    double damped = 0.0; // kinetic energy removed by kinetic damping since t = 0 (>= 0)
    // The change of Π at the reference moves since t = 0 (only when a function object asks for
    // it, needsMoveEnergy): their sum, the sum of the positive ones and the largest one.
    double moveSum = 0.0;
    double moveGain = 0.0;
    double moveLargest = 0.0;
    double total = 0.0;
    double drift = 0.0;
};

// The rigid walls (constant/walls) at a time level, by wall.
template <int D>
struct WallLoads
{
    std::vector<std::string> names;
    std::vector<Vec<D>> force;       // Σ_a (F_n + F_t): the force the wall exerts on the solid
    // Σ_a F_n, the normal part of `force`: for a plane its magnitude is Σ_a |F_n|; for a box
    // (walls/box) the contacts on opposite faces cancel in it, as in the load they put on it.
    std::vector<Vec<D>> normalForce;
    std::vector<double> work;        // its work on the solid since t = 0 (the energy audit's)
};

// What a function object sees at time level n (after the forces at x^n).
template <int D>
struct StepState
{
    long step = 0;
    double time = 0.0;
    double deltaT = 0.0;
    const ParticleSet<D>& particles;           // x^n, X, V0, m, bodies, fixed, F^n, P^n
    const std::vector<Vec<D>>& velocity;       // v^n (synchronised)
    const ReferenceConfiguration<D>& reference;
    const Kernel& kernel;
    const std::vector<std::string>& bodyNames;
    // The energy balance of this level; null unless some function object (needsEnergy) or
    // the run log asked for it (the strain energy costs a little in every scheme).
    const EnergyBalance* energy = nullptr;
    // The walls' loads of this level (after the wall forces at x^n); null without walls.
    const WallLoads<D>* walls = nullptr;
    // Which particles this rank owns, and the reductions over the ranks (serial: all, none).
    const ParticleRanks* ranks = nullptr;
    const ParticleRanks& rankView() const
    {
        static const ParticleRanks serial;
        return ranks ? *ranks : serial;
    }
};

template <int D>
class FunctionObject : public RegisteredModel
{
public:
    static constexpr const char* family = "functionObject";
    static constexpr int dimension = D;
    struct Args
    {
        std::string name;                                   // the entry name in `functions`
        std::filesystem::path caseDir;
        const ParticleSet<D>* initial = nullptr;            // the initial state (v = v^0)
        const std::vector<const Material<D>*>* materials = nullptr; // by body
        const std::vector<std::string>* bodyNames = nullptr;
        // Where a function object declares per-particle fields of its own (history it keeps
        // per particle: written, restarted and listed by -listTypes with no solver edit).
        ParticleFields<D>* fields = nullptr;
        const std::vector<std::string>* wallNames = nullptr; // constant/walls, in order
        bool artificialViscosity = false; // a viscosity other than `none` is selected
        bool kineticDamping = false;      // the integrator resets the velocities at KE peaks
        double endTime = 0.0;             // controlDict's endTime [s]
        // Whether every particle's F is the map from its initial position. Not so where gradF
        // elasticState moves a plastic material's reference: its F is then a dilation frame
        // carried with the samples' elastic state (docs/theory/gradF-plastic.md §G2, §G11).
        bool totalDeformationGradient = true;
        // A distributed run's ranks (null: serial); filled in before the first step, so a
        // constructor may only keep the pointer.
        const ParticleRanks* ranks = nullptr;
    };

    virtual ~FunctionObject() = default;

    const std::string& name() const { return name_; }
    // The prefix of this object's saveState() keys in the solver's restart data.
    std::string statePrefix() const { return "fo:" + name_ + ":"; }

    // Whether execute() at (step, time) needs the energy balance.
    virtual bool needsEnergy(long step, double time) const
    {
        (void)step;
        (void)time;
        return false;
    }
    // Whether it tabulates what each move of the reference configuration does to the strain
    // energy (the solver then evaluates Π just before every move: one energy evaluation per
    // move; docs/theory/gradF-plastic.md §G6).
    virtual bool needsMoveEnergy() const { return false; }
    // Whether it runs on several ranks: visits only the particles of state.rankView() that
    // count() and combines its results over the ranks (ParticleRanks). Otherwise a distributed
    // run refuses the case (a rank holds ghosts too: it would count them).
    virtual bool distributable() const { return false; }
    // Opens the output; a restart keeps the rows before `startTime` and appends.
    virtual void start(double startTime, bool restarted) = 0;
    virtual void execute(const StepState<D>& state) = 0;
    // Lines for the end-of-run summary (e.g. error norms).
    virtual std::vector<std::string> report() const { return {}; }
    // Named results for the run's postProcessing/summary.json (e.g. error norms)...
    virtual std::map<std::string, double> results() const { return {}; }
    // ...and words (e.g. a verdict), written as JSON strings.
    virtual std::map<std::string, std::string> textResults() const { return {}; }
    // Running quantities that a restart must continue (energy reference, error norms, ...).
    // The first time after the level at `time` at which this object writes (+inf: none in
    // particular); the solver lands a level on it under writeControl adjustableRunTime.
    virtual double nextWriteTime(double /*time*/, double /*deltaT*/) const
    {
        return std::numeric_limits<double>::infinity();
    }
    virtual void saveState(std::map<std::string, double>&) const {}
    virtual void restoreState(const std::map<std::string, double>&) {}

protected:
    explicit FunctionObject(std::string name) : name_(std::move(name)) {}

private:
    std::string name_;
};

} // namespace sph
