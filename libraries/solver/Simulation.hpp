#pragma once
// One run of the solid solver in dimension D: builds every model named by the case, then runs
// the time loop (spec §10), one time level n after another:
//
//   reference   move the reference configuration to x^n when the formulation says so
//   forces      T^n, F^n, P^n (and Π^n when wanted) at x^n
//   viscosity   the artificial viscosity's accelerations at x^n, v^{n-1/2}, F^n (not `none`)
//   time step   Δt_n (the time integrator: α h / max c when due, collapse check)
//   accelerate  a^n = T^n/m + g; fixed particles none
//   viscous     a^n += the viscous accelerations; their work (artificialViscosity/)
//   walls       a^n += F_wall/m at x^n, t^n (friction needs Δt_n); the walls' work
//   observe     v^n, the energy audit, the function objects, the progress line
//   output      VTK when due (the last good level is remembered for a failure)
//   commit      materials with history commit their state at F^n (after the output, so the
//               file of level n holds the state the forces at x^n used: a restart recomputes
//               them bit-identically; docs/theory/plasticity.md §P7)
//   drift       x^{n+1}, v^{n+1/2} (the time integrator); gravity work
//   contact     Δv on v^{n+1/2} at x^{n+1} (spec §9, §12)
//   order       1D: particles must not pass each other
//
// Fixed particles keep x and v = 0; their force is discarded (they stay in every kernel sum).
// A numerical failure (det F <= 0, NaN, particles crossing in 1D, Δt collapse) writes the last
// good level and throws NumericalFailure naming step, time, particle and quantity.
// A stop asked for while running (SIGTERM, SIGINT, `stopAt writeNow`: solver/StopRequest.hpp)
// makes the next level the last: it is written like the level at endTime, restartable.

#include "artificialViscosity/ArtificialViscosity.hpp"
#include "contact/Contact.hpp"
#include "core/CaseDictionaries.hpp"
#include "core/InputError.hpp"
#include "core/WriteSchedule.hpp"
#include "formulations/ReferenceManager.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "io/PvdSeries.hpp"
#include "parallel/ParticleExchange.hpp"
#include "solver/CaseSettings.hpp"
#include "solver/EnergyAudit.hpp"
#include "solver/ParticleFile.hpp"
#include "solver/RunLog.hpp"
#include "solver/StateFile.hpp"
#include "solver/StopRequest.hpp"
#include "stabilisation/Impenetrability.hpp"
#include "timeIntegration/KineticDamping.hpp"
#include "timeIntegration/TimeIntegration.hpp"
#include "walls/WallSet.hpp"

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sph
{

template <int D>
class Simulation
{
public:
    Simulation(const CaseDictionaries& dicts, const ControlSettings& control,
               const SchemeSettings& schemes, const InitialParticles& initial);
    ~Simulation();

    // The run header: case, dimension, models with their coefficients.
    std::vector<std::string> describe() const;
    RunSummary run(RunLog& log);
    // What a dry run checks beyond construction: on several ranks, the partition and each
    // rank's initial neighbourhoods (a serial run checked them when it was built).
    void checkSetup();

    const ParticleSet<D>& particles() const { return particles_; }
    // After run(): what stopped it before endTime ("SIGTERM", "stopAt writeNow"), else "".
    const std::string& stoppedBy() const { return stoppedBy_; }

private:
    // A time level as the writer sees it: read-only, the current one or the last good one.
    struct LevelView
    {
        long step = 0;
        double time = 0.0;
        bool restartable = true;
        const std::vector<Vec<D>>* x = nullptr; // positions of that level
    };

    // SimulationSetup.cpp
    void loadParticles(const InitialParticles& initial);
    void setupWalls();
    void setupViscosity(const SchemeSettings& schemes);
    void setupImpenetrability(const SchemeSettings& schemes);
    void setupFunctionObjects();
    void checkCrossingOrder();
    // SimulationOperatorProbe.cpp (docs/theory/timeStep.md)
    void setupOperatorProbe(); // stepBound operator: the probe, or why not (§T4)
    // The operator's largest frequency at this level (§T3); leaves the level's own forces, F, P
    // and scratch states as they were.
    typename OperatorProbe<D>::Result probeOperator(int iterations, std::vector<Vec<D>>& mode);
    // SimulationBodies.cpp
    void setupBodies(const Dictionary& bodies);
    // Sets body b's initial stress (constant/bodies: initialStress { type ...; }).
    void setInitialStress(const Dictionary& dict, std::size_t b);
    void checkWaveSpeed(const Dictionary& material, std::size_t b) const; // step <= endTime

    using FunctionState = std::map<std::string, double>; // "fo:<name>:<key>" -> value

    // Simulation.cpp: the time loop and its phases (reads -> writes); the forces of a level in
    // SimulationForces.cpp, the moves of the reference in SimulationMoves.cpp, the motion of a
    // step (drift to checkOrder) in SimulationMotion.cpp
    void advance(RunLog& log, bool restarted);
    // This rank's request to stop (StopCode: a signal's number, writeNow, none); rank 0 reads
    // controlDict again when it changed.
    int stopRequest(RunLog& log);
    // The step from this level (see writeControl): its length, and whether it ends exactly on
    // an output time `target` (then the new time is set to it, free of accumulated round-off).
    struct Step
    {
        double dt = 0.0;
        bool landsOnTarget = false;
        double target = 0.0;
    };
    Step stepToTake() const;
    bool outputDueNow() const; // the VTK output is due at this level
    bool energyWanted(long firstStep) const;      // the function objects' needs -> bool
    // SimulationMoves.cpp: the reference's part of a level (and the split kick's, below)
    bool moveReference(long firstStep);           // x^n -> the reference configuration
    double strainEnergyNow();                     // x^n, the reference as it is -> Π
    std::vector<std::string> fieldsAMoveChanges() const; // what ghosts refresh after a move
    ForceInput<D> forceInput(bool atReference);   // x^n, the reference -> the scheme's input
    ForceStatus computeForces(bool atReference,   // x^n, reference -> T (in acceleration_),
                              bool wantEnergy);   //   F^n, P^n, Π^n
    ForceStatus internalForces(const ForceInput<D>& in, // scheme + close-pair energy -> T,
                               std::vector<Vec<D>>& T,  //   F, P in the spare buffers, Π
                               bool wantEnergy);
    // The kick split at a move (updatedLagrangian splitKick, gradF-plastic.md §G20):
    void computeClosingForces();                  // x^n, the reference before the move -> T_close
    void keepClosingDifference();                 // T_close, the level's T -> T_close - T
    void afterLevelForces();                      // F^n -> the strain since the move; T_close - T
    const std::vector<Vec<D>>& closingAcceleration(); // a^n, T_close - T, m -> a^n_close
    void accelerate();                            // T, m, g, fixed -> a^n (in place)
    void applyWalls(double dt);                            // x^n, v^{n-1/2}, a, Δt_n -> a^n += F_wall/m,
                                                  //   Φ^n, wall loads; W_walls (friction)
    void computeViscosity();                      // x^n, v^{n-1/2}, F^n -> a_visc^n
    void applyViscosity();                        // a_visc^n -> a^n += (before the walls: their
                                                  //   friction sees it); W_visc (second half)
    void chooseTimeStep(bool freshStart,          // F^n -> the integrator's Δt_n
                        bool firstLevel);
    void checkRunLength(double deltaT) const;     // Δt_0 against endTime and writeInterval
    FunctionState functionObjectState() const;    // function objects -> their restart state
    void observe(RunLog& log, double dt,          // v, a^n, Π^n -> v^n, energy balance,
                 double strainEnergy, bool wantEnergy,  // function objects, progress line
                 bool progress, long firstStep);
    void writeLevel(RunLog& log, const FunctionState& functionState); // registries -> VTK/
    void commitHistory();                         // F^n -> the materials' history; D
    void drift(double dt);                        // x^n, v, a^n -> x^{n+1}, v^{n+1/2}; W_g,
                                                  //   W_walls (motion, friction)
    void applyContact(double dt);                 // x^{n+1}, F(x^{n+1}) -> Δv, W_contact
    void dampKinetic(double dt);                  // v^{n+1/2} -> 0 at a peak of K; K_damped
    void checkOrder(double dt);                   // 1D: x^{n+1} -> failure if out of order
    WaveSpeedBound waveSpeedBound() const;
    double waveSpeedOf(std::size_t b, std::size_t first, std::size_t n) const;
    [[noreturn]] void fail(const ForceStatus& status, const std::string& when);
    std::string describeFailure(const ForceStatus& status, const std::string& when) const;
    // Writes the last good level and throws NumericalFailure with the diagnosis.
    [[noreturn]] void failWith(const std::string& diagnosis);
    long crossingParticle() const;
    std::string particleName(std::size_t a) const;
    std::string energyGrowthNote() const; // a failure after the energy grew: what may feed it
    // The setup's error for a particle whose corrected gradient is singular in the initial
    // configuration (the run cannot start; serially at construction, distributed at the first
    // gathering of each rank's particles).
    InputError tooFewNeighbours(const std::string& particle, const std::string& what) const;

    // SimulationDistributed.cpp and SimulationGhosts.cpp (the ghost layer): a run on several
    // ranks (sphSolid -parallel; docs/parallel.md)
    bool distributed() const { return exchange_ != nullptr; }
    void checkDistributable() const;   // the models a distributed run supports, else InputError
    void distribute();                 // every rank's whole set -> owned particles + ghosts
    void shareRanks();                 // ranks_: owned particles, reductions, the writer
    bool regatherDue() const;          // a particle moved more than half the ghosts' skin
    void regather();                   // new ghosts around the owned particles (after a move of
                                       //   the reference configuration, or contact's drift)
    void localParticlesChanged();      // body ranges, owned mask, reference data of the new set
    void refreshGhosts(const std::vector<std::string>& names); // owners' values -> ghosts
    void refreshGhostPositions();      // x^{n+1} of the owners (each step)
    // Fails when the status does (distributed: when any rank's does, with the diagnosis of the
    // failing particle of least global index, on every rank).
    void checkStatus(const ForceStatus& status, const std::string& when);
    // Collective: the rank owning the failing particle with the least global index, which
    // words the diagnosis every rank reports (-1: no rank has one; badParticle < 0: none here).
    int wordingRank(long badParticle) const;
    double ghostWidth() const;         // how far from its owned particles a rank needs ghosts
    double ghostSkin() const;          // the part of it that lets particles move between gathers
    double currentReach() const;       // how far models read other particles in x (0: none)
    double currentSkin() const;        // the part of the ghosts in x that lets particles move
    bool currentRegatherDue() const;   // a particle moved more than half that skin
    void followMovingParticles();      // after the drift: regather when currentRegatherDue()
    void refreshGhostVelocities();     // the owners' v (the viscosity reads them)
    bool movedFarther(const std::vector<Vec<D>>& now, const std::vector<Vec<D>>& then,
                      double distance) const; // some owned particle, on any rank
    long globalIndex(std::size_t a) const; // the particle's index in the whole set
    std::string distributionReport(long steps) const; // repartitions, ghosts, bytes per step
    // This rank's piece (+ .pvtu on rank 0): its owned particles.
    void writePieces(const VtuData& header, const std::vector<std::size_t>& ownedParticles,
                     double time);

    // SimulationOutput.cpp
    // Declares every per-particle field and run scalar of the solver itself (the models
    // declare their own).
    void declareFields();
    // postProcessing/summary.json: models, status, cost and the function objects' results.
    void writeSummary(const RunSummary& summary, const std::string& failure) const;
    void removeOldOutput();
    void writeOutput(const LevelView& level, const FunctionState& functionState);
    // startFrom latestTime: the newest restartable output (false: none, start afresh);
    // startFrom startTime with startTime > 0: the output written at that time (InputError when
    // there is none, listing the written times).
    bool restoreLatest(RunLog& log);

    const CaseDictionaries& dicts_;
    ControlSettings control_;
    std::string caseName_;
    ParticleSet<D> particles_;
    // Every per-particle field and run scalar: what output and restart iterate over (before
    // the models, which may keep references into it).
    ParticleFields<D> fields_;
    RunScalars runScalars_;
    std::vector<std::string> bodyNames_;
    double spacing_ = 0.0;
    SourceLocation kernelLocation_; // where hOverDx is set (or the kernel's dictionary)
    bool neighbourhoodsChecked_ = false; // a distributed run's first gathering has checked them
    Vec<D> gravity_ = Vec<D>::Zero();

    std::unique_ptr<Kernel> kernel_;
    std::vector<std::unique_ptr<Material<D>>> materialModels_;
    std::vector<const Material<D>*> materials_;
    bool historyMaterials_ = false; // some body's material keeps a per-particle history
    // A function object tabulates the reference moves' energy (needsMoveEnergy), and Π just
    // before the move of this step, while its change is still to be booked.
    bool moveEnergyWanted_ = false;
    std::optional<double> energyBeforeMove_;
    // updatedLagrangian's splitKick, and whether this level's kick is split (the reference
    // moved here): the forces of the reference before the move, as T_close, then T_close - T
    // (a field, so that a move's regathering carries it with its particle), and a^n_close.
    bool splitKick_ = false;
    bool kickSplitHere_ = false;
    std::vector<Vec<D>> closingForce_;
    std::vector<Vec<D>> closingAcceleration_;
    // How the level's own forces were evaluated (the probe evaluates them again so).
    bool levelAtReference_ = false;
    bool levelWantsEnergy_ = false;
    // The longest step the walls allow when the step follows the operator (timeStep.md §T4).
    double wallDeltaT_ = std::numeric_limits<double>::infinity();
    std::unique_ptr<Formulation<D>> formulation_;
    std::unique_ptr<Stabilisation<D>> scheme_;
    std::unique_ptr<Contact<D>> contact_;
    std::unique_ptr<WallSet<D>> walls_; // constant/walls (empty without the file)
    std::unique_ptr<ArtificialViscosity<D>> viscosity_;
    std::unique_ptr<Impenetrability<D>> impenetrability_; // null: not in sphSchemes
    std::unique_ptr<TimeIntegration<D>> integrator_;
    std::optional<KineticDamping<D>> damping_; // the integrator's kineticDamping
    std::vector<std::unique_ptr<FunctionObject<D>>> functionObjects_;
    std::unique_ptr<ReferenceManager<D>> reference_;
    std::vector<std::vector<std::size_t>> barOrder_; // 1D: each body's particles sorted by X

    EnergyAudit<D> audit_;
    WriteSchedule outputSchedule_;
    long step_ = 0;
    double time_ = 0.0;
    long outputIndex_ = 0;
    LevelView lastGood_{-1, 0.0, false, nullptr}; // the last level that passed every check
    // The last energy balance's drift and its time (a failure's diagnosis reads it).
    std::optional<std::pair<double, double>> lastDrift_;
    const std::vector<Vec<D>>* writtenX_ = nullptr; // the positions being written

    // Work arrays, allocated once.
    std::vector<Vec<D>> acceleration_;   // the internal force T, then a = T/m + g in place
    std::vector<Vec<D>> velocitySync_;   // v^n
    std::vector<Vec<D>> previousX_;      // x of the last good level
    std::vector<Vec<D>> contactDeltaV_;
    std::vector<Vec<D>> dampingDeltaV_;  // the v^{n+1/2} the last reset removed (kinetic damping)
    std::vector<Vec<D>> viscousAcceleration_; // a_visc^n (artificial viscosity only)
    std::vector<Mat<D>> nextF_;
    std::vector<Mat<D>> nextP_;

    PvdSeries pvd_;

    // A distributed run (null/empty in a serial one): the ranks, the owned and ghost particles,
    // each local particle's index in the whole set, and which local particles this rank owns.
    Communicator comm_ = Communicator::world();
    std::unique_ptr<ParticleExchange<D>> exchange_;
    std::vector<int> globalId_;
    std::vector<std::uint8_t> owned_;
    ParticleRanks ranks_; // what the models see of it (serial: every particle, no reductions)
    std::size_t globalCount_ = 0; // particles in the whole set
    long repartitions_ = 0;       // migrations after the start (maxLoadImbalance)
    long gathers_ = 0;            // ghost layers gathered (the start, then as particles move)
    std::vector<Vec<D>> gatheredAt_; // the local particles' x^r when the ghosts were gathered
    std::vector<Vec<D>> gatheredX_;  // and their x (contact, viscosity)
    std::string lastOutputFile_;  // in VTK/, the last output written (.vtu or .pvtu)

    // A graceful stop (solver/StopRequest.hpp): controlDict's stopAt while running (rank 0),
    // and what stopped the run ("" when it reached endTime).
    std::optional<ControlDictWatch> controlWatch_;
    std::string stoppedBy_;
};

} // namespace sph
