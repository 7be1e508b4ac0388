// The time loop of the solid solver and its phases (see Simulation.hpp for the algorithm).
#include "solver/Simulation.hpp"

#include "core/Application.hpp"
#include "core/Format.hpp"
#include "io/AtomicFile.hpp"
#include "particles/Parallel.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

namespace sph
{

template <int D>
RunSummary Simulation<D>::run(RunLog& log)
{
    // A run killed while writing left its temporaries (io/AtomicFile) beside the outputs:
    // nothing reads them, so they would only pile up.
    if (comm_.parallel())
    {
        checkDistributable(); // before any file is read or removed
    }
    if (comm_.rank() == 0)
    {
        for (const char* folder : {"VTK", "postProcessing"})
        {
            removeStaleTemporaries(dicts_.caseDir() / folder);
        }
    }
    // SIGTERM and SIGINT ask for a graceful stop while the run is under way (restored after).
    const StopSignals stopSignals;
    controlWatch_.emplace(dicts_.caseDir(), control_.stopAtWriteNow);
    const bool restarted =
        (control_.startFromLatest || control_.startTime) && restoreLatest(log);
    if (!restarted)
    {
        comm_.barrier(); // every rank has looked through VTK/ before rank 0 clears it
        removeOldOutput();
    }
    if (comm_.parallel())
    {
        comm_.barrier(); // rank 0 has cleared the old output
        distribute();
    }
    for (auto& object : functionObjects_)
    {
        object->start(time_, restarted);
    }
    const long firstStep = step_;
    log.startTimer(time_, control_.endTime, distributed() ? globalCount_ : particles_.size());
    try
    {
        advance(log, restarted);
    }
    catch (const NumericalFailure& failure)
    {
        writeSummary(log.finish(step_ - firstStep, time_), failure.what());
        throw;
    }
    for (const auto& object : functionObjects_)
    {
        for (const auto& line : object->report())
        {
            log.line(line);
        }
    }
    if (formulation_->movesByStrain())
    {
        // How often the motion moved the reference (the schedule is not in steps).
        log.line("Reference   moved " + std::to_string(reference_->moves()) + " times in " +
                 std::to_string(step_ - firstStep) + " steps (referenceUpdateStrain)");
    }
    if (distributed())
    {
        const std::string report = distributionReport(step_ - firstStep);
        log.line(report);
    }
    if (!stoppedBy_.empty())
    {
        log.line("Stopped     by " + stoppedBy_ + " at step " + std::to_string(step_) +
                 ", t = " + formatNumber(time_, 9) + " s (written, restartable: continue with "
                 "'startFrom latestTime;'" +
                 (stoppedBy_ == StopCode::describe(StopCode::writeNow)
                      ? " and 'stopAt endTime;' in system/controlDict)"
                      : ")"));
    }
    const RunSummary summary = log.finish(step_ - firstStep, time_);
    writeSummary(summary, "");
    comm_.barrier(); // no rank leaves before the output is complete
    return summary;
}

template <int D>
void Simulation<D>::advance(RunLog& log, bool restarted)
{
    const long firstStep = step_;
    while (true)
    {
        const bool atReference = moveReference(firstStep);
        // The progress line is due by the wall clock, which each rank reads differently; the
        // energy sums it triggers are collective, so the ranks agree first. A stop asked for on
        // any rank (a signal) or on rank 0 (controlDict) is agreed on in the same reduction, so
        // every rank stops at this level.
        std::vector<double> due{log.progressDue() ? 1.0 : 0.0,
                                static_cast<double>(stopRequest(log))};
        if (distributed())
        {
            comm_.maximum(due);
        }
        const bool progress = due[0] > 0.0;
        const int stop = static_cast<int>(due[1]);
        const bool wantEnergy = progress || energyWanted(firstStep) || energyBeforeMove_;
        const ForceStatus forces = computeForces(atReference, wantEnergy);
        afterLevelForces();
        levelAtReference_ = atReference;
        levelWantsEnergy_ = wantEnergy;
        if (energyBeforeMove_)
        {
            audit_.addMoveChange(forces.strainEnergy - *energyBeforeMove_);
            energyBeforeMove_.reset();
        }
        computeViscosity();
        chooseTimeStep(step_ == firstStep && !restarted, step_ == firstStep);
        // The run ends at the first level at or after endTime (no shortened last step: a run
        // stopped early follows the same trajectory, so restarts continue bit-identically).
        const bool endReached = time_ >= control_.endTime * (1.0 - 1e-12) ||
                                (control_.maxSteps && step_ - firstStep >= *control_.maxSteps);
        // A stop makes this level the last one, written like the one at endTime.
        const bool last = endReached || stop != StopCode::none;
        if (last && !endReached)
        {
            stoppedBy_ = StopCode::describe(stop);
            log.line("Stopping    " + stoppedBy_ + ": writing step " + std::to_string(step_) +
                     ", t = " + formatNumber(time_, 9) + " s");
        }
        const Step step = stepToTake();
        accelerate();
        applyViscosity();
        applyWalls(step.dt);
        // The step that ends here closes with a^n_close (v^n): the audit's kicks complete with it.
        const std::vector<Vec<D>>& closing = kickSplitHere_ ? closingAcceleration() : acceleration_;
        audit_.completeContactWork(particles_.m, contactDeltaV_, closing);
        audit_.completeDamping(particles_.m, dampingDeltaV_, closing);
        if (kickSplitHere_)
        {
            integrator_->closeAtLevel(closing);
        }
        const double dt = last ? 0.0 : step.dt;
        const bool outputDue = last || outputDueNow();
        // The function objects' restart state is that from before they see this level.
        const auto functionState = outputDue ? functionObjectState() : FunctionState{};
        observe(log, dt, forces.strainEnergy, wantEnergy, progress, firstStep);
        if (outputDue)
        {
            writeLevel(log, functionState);
        }
        lastGood_ = {step_, time_, false, &previousX_}; // x^n is in previousX_ after the drift
        if (last)
        {
            break;
        }
        commitHistory();
        drift(dt);
        refreshGhostPositions();
        followMovingParticles();
        applyContact(dt);
        dampKinetic(dt);
        refreshGhostVelocities();
        checkOrder(dt);
        time_ = step.landsOnTarget ? step.target : time_ + dt;
        ++step_;
    }
}

template <int D>
int Simulation<D>::stopRequest(RunLog& log)
{
    if (const int signal = StopSignals::caught())
    {
        return signal;
    }
    const bool writeNow =
        comm_.rank() == 0 &&
        controlWatch_->writeNow([&log](const std::string& warning) { log.line(warning); });
    return writeNow ? StopCode::writeNow : StopCode::none;
}

// Under writeControl adjustableRunTime the time left to the next output or function-object
// row is split into equal steps no longer than the integrator's Δt_n (OpenFOAM's adjustable
// run time): the level lands on that time exactly, and no step is a sliver. The targets are
// restart state, so a restarted run takes the same steps. endTime is not a target: a run
// stopped there and continued must follow the uninterrupted run.
template <int D>
typename Simulation<D>::Step Simulation<D>::stepToTake() const
{
    const double deltaT = integrator_->deltaT();
    if (control_.writeControl != WriteControl::adjustableRunTime)
    {
        return {deltaT};
    }
    double target = outputSchedule_.nextAfter(time_, deltaT);
    for (const auto& object : functionObjects_)
    {
        target = std::min(target, object->nextWriteTime(time_, deltaT));
    }
    const double gap = target - time_;
    if (!(gap > 0.0) || !std::isfinite(gap))
    {
        return {deltaT};
    }
    // Within round-off of a whole number of steps: that number (no extra sliver step).
    const double steps = std::ceil(gap / deltaT * (1.0 - 1e-9));
    if (steps > 1e15)
    {
        return {deltaT};
    }
    return {gap / steps, steps == 1.0, target};
}

template <int D>
bool Simulation<D>::outputDueNow() const
{
    if (control_.writeControl == WriteControl::timeStep)
    {
        return step_ % static_cast<long>(control_.writeInterval) == 0;
    }
    return outputSchedule_.due(time_, integrator_->deltaT());
}

template <int D>
typename Simulation<D>::FunctionState Simulation<D>::functionObjectState() const
{
    FunctionState state;
    for (const auto& object : functionObjects_)
    {
        std::map<std::string, double> own;
        object->saveState(own);
        for (const auto& [key, value] : own)
        {
            state[object->statePrefix() + key] = value;
        }
    }
    return state;
}

template <int D>
void Simulation<D>::writeLevel(RunLog& log, const FunctionState& functionState)
{
    const auto start = std::chrono::steady_clock::now();
    writeOutput({step_, time_, true, &particles_.x}, functionState);
    outputSchedule_.written(time_, integrator_->deltaT());
    log.addOutputSeconds(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

// The materials with history commit their state at F^n (the scheme says how: gradF keeps
// one per stress sample); the dissipation enters the energy audit.
template <int D>
void Simulation<D>::commitHistory()
{
    if (!historyMaterials_)
    {
        return;
    }
    std::vector<Material<D>*> withHistory;
    for (const auto& material : materialModels_)
    {
        withHistory.push_back(material->hasHistory() ? material.get() : nullptr);
    }
    const double dissipated = scheme_->commitHistory(
        {particles_.F, particles_.V0, particles_.bodies, withHistory, distributed() ? &owned_ : nullptr});
    audit_.addDissipation(distributed() ? comm_.sum(dissipated) : dissipated);
}

template <int D>
bool Simulation<D>::energyWanted(long firstStep) const
{
    bool wanted = step_ == firstStep; // the reference of the drift
    for (const auto& object : functionObjects_)
    {
        wanted = wanted || object->needsEnergy(step_, time_);
    }
    return wanted;
}

template <int D>
void Simulation<D>::chooseTimeStep(bool freshStart, bool firstLevel)
{
    const ForceStatus status = integrator_->chooseTimeStep(step_, freshStart, waveSpeedBound());
    checkStatus(status, "computing the time step");
    if (firstLevel)
    {
        checkRunLength(integrator_->deltaT());
    }
}

// v^n, the energy balance (when wanted), the function objects and the progress line.
template <int D>
void Simulation<D>::observe(RunLog& log, double dt, double strainEnergy, bool wantEnergy,
                            bool progress, long firstStep)
{
    integrator_->synchronise(acceleration_, velocitySync_);
    EnergyBalance balance;
    if (wantEnergy)
    {
        balance = audit_.balance(particles_.m, velocitySync_, strainEnergy, walls_->potential());
        lastDrift_ = {time_, balance.drift};
    }
    WallLoads<D> walls;
    if (!walls_->empty())
    {
        walls = walls_->loads();
        walls.work = audit_.wallWork();
    }
    const StepState<D> state{step_,       time_,      dt,        particles_,
                             velocitySync_, reference_->reference(), *kernel_, bodyNames_,
                             wantEnergy ? &balance : nullptr, walls_->empty() ? nullptr : &walls,
                             &ranks_};
    for (auto& object : functionObjects_)
    {
        object->execute(state);
    }
    if (progress)
    {
        log.progress(step_, step_ - firstStep, time_, integrator_->deltaT(), balance.drift, true,
                     integrator_->stepNote());
    }
}

template class Simulation<1>;
template class Simulation<2>;
template class Simulation<3>;

} // namespace sph
