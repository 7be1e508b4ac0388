#pragma once
// One run of the solid solver in dimension D: builds every model named by the case, then
// advances the particles with the leapfrog scheme of seed eqs. (15)-(16) (spec §10):
//
//   a^n = (T(x^n) + m g)/m,  v^{n+1/2} = v^{n-1/2} + ½(Δt_{n-1} + Δt_n) a^n,
//   x^{n+1} = x^n + Δt_n v^{n+1/2},   Δt_n = α h / max_a c(F_a),
//
// with v^{1/2} = v^0 + ½Δt_0 a^0 at the start. Function objects see each time level n with the
// synchronised velocity v^n = v^{n-1/2} + ½Δt_{n-1} a^n. Fixed particles keep x and v = 0;
// their force is discarded (they stay in every kernel sum).
//
// A numerical failure (det F <= 0, NaN, particles crossing in 1D, Δt collapse) writes the last
// good state and throws NumericalFailure naming step, time, particle and quantity.

#include "contact/Contact.hpp"
#include "core/CaseDictionaries.hpp"
#include "formulations/ReferenceManager.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "io/PvdSeries.hpp"
#include "solver/CaseSettings.hpp"
#include "solver/ParticleFile.hpp"
#include "solver/RunLog.hpp"
#include "solver/StateFile.hpp"

#include <memory>
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

    const ParticleSet<D>& particles() const { return particles_; }

private:
    // SimulationSetup.cpp
    void loadParticles(const InitialParticles& initial);
    void setupBodies(const Dictionary& bodies);
    void setupFunctionObjects();
    void checkCrossingOrder();

    // Simulation.cpp
    void advance(RunLog& log, bool restarted); // the time loop
    // α h / max c over the particles, and the particle with the largest wave speed.
    std::pair<double, std::size_t> stableTimeStep() const;
    void fail(const ForceStatus& status, const std::string& when);
    long crossingParticle() const;
    std::string particleName(std::size_t a) const;

    // SimulationOutput.cpp
    // Declares every per-particle field and run scalar of the solver itself (the models
    // declare their own).
    void declareFields();
    // postProcessing/summary.json: models, status, cost and the function objects' results.
    void writeSummary(const RunSummary& summary, const std::string& failure) const;
    void removeOldOutput();
    void writeOutput(bool restartable, long step, double time,
                     const std::map<std::string, double>& functionState);
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
    Vec<D> gravity_ = Vec<D>::Zero();

    std::unique_ptr<Kernel> kernel_;
    std::vector<std::unique_ptr<Material<D>>> materialModels_;
    std::vector<const Material<D>*> materials_;
    std::unique_ptr<Formulation<D>> formulation_;
    std::unique_ptr<Stabilisation<D>> scheme_;
    std::unique_ptr<Contact<D>> contact_;
    std::vector<std::unique_ptr<FunctionObject<D>>> functionObjects_;
    std::unique_ptr<ReferenceManager<D>> reference_;
    std::vector<std::vector<std::size_t>> barOrder_; // 1D: each body's particles sorted by X

    // Time state (all of it goes into every output, so a restart continues exactly).
    long step_ = 0;
    double time_ = 0.0;
    double deltaT_ = 0.0;         // Δt of the most recent step (Δt_{n-1} at level n)
    double previousDeltaT_ = 0.0; // Δt_{n-1}, used for v^n and v^{n+1/2}
    bool halfStepVelocity_ = false; // particles_.v holds v^{n-1/2} (false: v^0 at the start)
    long outputIndex_ = 0;
    double nextOutputTime_ = 0.0;
    double externalWork_ = 0.0;
    double contactWork_ = 0.0;
    // The contact kick's work needs a^{n+1}: its last part is added at the next level.
    bool contactWorkPending_ = false;
    double contactDeltaT_ = 0.0;
    double firstDeltaT_ = 0.0; // Δt_0: a step below 1e-6 of it is a collapse
    double initialEnergy_ = 0.0;
    bool haveInitialEnergy_ = false;
    long lastGoodStep_ = -1;
    double lastGoodTime_ = 0.0;

    // Work arrays, allocated once.
    std::vector<Vec<D>> acceleration_;   // the internal force T, then a = T/m + g in place
    std::vector<Vec<D>> velocitySync_;   // v^n
    std::vector<Vec<D>> previousX_;      // x of the last good level
    std::vector<Vec<D>> contactDeltaV_;
    std::vector<Mat<D>> nextF_;
    std::vector<Mat<D>> nextP_;

    PvdSeries pvd_;
};

} // namespace sph
