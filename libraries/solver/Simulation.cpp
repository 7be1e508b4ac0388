// The time loop of the solid solver (see Simulation.hpp for the scheme).
#include "solver/Simulation.hpp"

#include "core/Application.hpp"
#include "particles/Parallel.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

namespace sph
{

template <int D>
std::pair<double, std::size_t> Simulation<D>::stableTimeStep() const
{
    double c = 0.0;
    std::size_t body = 0;
    for (std::size_t b = 0; b < particles_.bodies.size(); ++b)
    {
        // In chunks, in parallel: a maximum does not depend on the order.
        const BodyRange& range = particles_.bodies[b];
        const std::size_t chunk = 1024;
        const long chunks = static_cast<long>((range.size() + chunk - 1) / chunk);
        double bodyC = 0.0;
#pragma omp parallel for schedule(static) reduction(max : bodyC) if (useThreads(range.size()))
        for (long i = 0; i < chunks; ++i)
        {
            const std::size_t first = range.begin + static_cast<std::size_t>(i) * chunk;
            const std::size_t count = std::min(chunk, range.end - first);
            bodyC = std::max(bodyC, materials_[b]->maxWaveSpeed(&particles_.F[first], count));
        }
        if (bodyC > c)
        {
            c = bodyC;
            body = b;
        }
    }
    // Only when reporting a collapse does the fastest particle matter: find it then.
    std::size_t fastest = particles_.bodies[body].begin;
    const double dt = control_.courant * kernel_->h() / c;
    if (!(dt > 1e-6 * firstDeltaT_) || !std::isfinite(dt))
    {
        const BodyRange& range = particles_.bodies[body];
        double best = -1.0;
        for (std::size_t a = range.begin; a < range.end; ++a)
        {
            const double ca = materials_[body]->waveSpeed(particles_.F[a]);
            if (!(ca <= best))
            {
                best = ca;
                fastest = a;
            }
        }
    }
    return {dt, fastest};
}

template <int D>
long Simulation<D>::crossingParticle() const
{
    if constexpr (D == 1)
    {
        for (const auto& order : barOrder_)
        {
            for (std::size_t i = 1; i < order.size(); ++i)
            {
                if (!(particles_.x[order[i]][0] > particles_.x[order[i - 1]][0]))
                {
                    return static_cast<long>(order[i]);
                }
            }
        }
    }
    return -1;
}

template <int D>
void Simulation<D>::fail(const ForceStatus& status, const std::string& when)
{
    std::ostringstream message;
    message << status.message;
    if (status.failure == FailureKind::nonPositiveJacobian)
    {
        message << " = " << status.badValue << " <= 0";
    }
    else if (status.failure == FailureKind::nonFiniteForce)
    {
        message << " is not finite";
    }
    message << " at " << particleName(static_cast<std::size_t>(status.badParticle)) << ", step "
            << step_ << ", t = " << time_ << " s, " << when << ".";
    // The last good level: positions in previousX_, F and P of its force evaluation.
    std::string written;
    if (lastGoodStep_ >= 0)
    {
        particles_.x.swap(previousX_);
        writeOutput(false, lastGoodStep_, lastGoodTime_, {});
        particles_.x.swap(previousX_);
        written = "The last good state (step " + std::to_string(lastGoodStep_) + ", t = " +
                  std::to_string(lastGoodTime_) + " s) is written to " +
                  pvd_.entries().back().file + " (listed in VTK/" + caseName_ + ".pvd).";
    }
    message << "\n" << written
            << "\nLikely causes: the scheme is unstable for this problem (try stabilisation gradF "
               "or formulation totalLagrangian), the time step is too large (lower courant), or "
               "the deformation is beyond the material model.";
    throw NumericalFailure(message.str());
}

template <int D>
RunSummary Simulation<D>::run(RunLog& log)
{
    const std::size_t n = particles_.size();
    const bool restarted = control_.startFromLatest && restoreLatest(log);
    if (!restarted)
    {
        removeOldOutput();
    }
    for (auto& object : functionObjects_)
    {
        object->start(time_, restarted);
    }
    const long firstStep = step_;
    log.startTimer(time_, control_.endTime, n);
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
    const RunSummary summary = log.finish(step_ - firstStep, time_);
    writeSummary(summary, "");
    return summary;
}

template <int D>
void Simulation<D>::advance(RunLog& log, bool restarted)
{
    const std::size_t n = particles_.size();
    const long firstStep = step_;
    const double endTime = control_.endTime;

    while (true)
    {
        // 1. Updated-Lagrangian: move the reference configuration when due.
        ForceStatus status;
        const bool moved = reference_->updateIfDue(step_, particles_, status);
        if (!status.ok())
        {
            fail(status, "moving the reference configuration");
        }
        // x is the reference configuration bitwise (f = I exactly) when the reference was just
        // moved here — or, at the first level of a run (fresh or restarted), if the arrays say
        // so (an initial displacement makes x differ from X = x^r).
        const bool atReference =
            moved || (step_ == firstStep && reference_->reference().updateStep == step_ &&
                      reference_->reference().x == particles_.x);

        // 2. Internal forces, F and P at x^n (into spare buffers: the last good F, P survive).
        const bool progress = log.progressDue();
        bool wantEnergy = progress || step_ == firstStep;
        for (const auto& object : functionObjects_)
        {
            wantEnergy = wantEnergy || object->needsStrainEnergy(step_, time_);
        }
        ForceInput<D> in{particles_.x, particles_.V0, particles_.body, particles_.bodies,
                         materials_, reference_->reference(), atReference};
        ForceOutput<D> out{acceleration_, nextF_, nextP_};
        status = scheme_->computeForces(in, out, wantEnergy);
        if (!status.ok())
        {
            fail(status, "computing the internal forces");
        }
        particles_.F.swap(nextF_);
        particles_.P.swap(nextP_);

        // 3. Accelerations (in place of the forces); fixed particles discard their force.
#pragma omp parallel for schedule(static) if (useThreads(n))
        for (std::size_t a = 0; a < n; ++a)
        {
            acceleration_[a] = particles_.fixed[a]
                                   ? Vec<D>::Zero()
                                   : Vec<D>(acceleration_[a] / particles_.m[a] + gravity_);
        }

        // Contact work of the last kick, ΔW = Σ m Δv·(v^{n+1/2} + ½Δv + ½Δt a^{n+1}) (spec
        // §12): the part with a^{n+1} now that it is known.
        if (contactWorkPending_)
        {
            double work = 0.0;
            for (std::size_t a = 0; a < n; ++a)
            {
                work += particles_.m[a] * contactDeltaV_[a].dot(acceleration_[a]);
            }
            contactWork_ += 0.5 * contactDeltaT_ * work;
            contactWorkPending_ = false;
        }

        // 4. Time step: α h / c from the current F, when due.
        const bool firstLevel = step_ == firstStep && !restarted;
        if (firstLevel ||
            (control_.timeStepUpdateInterval > 0 && step_ % control_.timeStepUpdateInterval == 0))
        {
            const auto [stable, fastest] = stableTimeStep();
            if (firstLevel && step_ == 0)
            {
                firstDeltaT_ = stable;
            }
            if (!(stable > 1e-6 * firstDeltaT_) || !std::isfinite(stable))
            {
                fail(ForceStatus::failed(FailureKind::timeStepCollapse, static_cast<long>(fastest),
                                         stable,
                                         "time step (collapsed to " + std::to_string(stable) +
                                             " s from " + std::to_string(firstDeltaT_) +
                                             " s; the largest wave speed is here)"),
                     "computing the time step");
            }
            deltaT_ = stable;
        }
        // The run ends at the first level at or after endTime (no shortened last step: a run
        // stopped early follows the same trajectory, so restarts continue bit-identically).
        const bool last = time_ >= endTime * (1.0 - 1e-12) ||
                          (control_.maxSteps && step_ - firstStep >= *control_.maxSteps);
        const double dt = last ? 0.0 : deltaT_;

        // 5. The synchronised velocity v^n (v^{n+1/2} follows after the output, in place: the
        //    output holds v^{n-1/2}, which a restart needs).
        const double syncFactor = halfStepVelocity_ ? 0.5 * previousDeltaT_ : 0.0;
#pragma omp parallel for schedule(static) if (useThreads(n))
        for (std::size_t a = 0; a < n; ++a)
        {
            velocitySync_[a] = particles_.v[a] + syncFactor * acceleration_[a];
        }

        // 6. Function objects and output at level n.
        // Outputs at the first level at or after each multiple of writeInterval (the tolerance
        // absorbs round-off in the accumulated time).
        const bool outputDue = last || time_ >= nextOutputTime_ - 1e-6 * deltaT_;
        std::map<std::string, double> functionState;
        if (outputDue)
        {
            for (const auto& object : functionObjects_)
            {
                std::map<std::string, double> own;
                object->saveState(own);
                for (const auto& [key, value] : own)
                {
                    functionState[object->statePrefix() + key] = value;
                }
            }
        }
        StepState<D> state{step_, time_, dt, particles_, velocitySync_, reference_->reference(),
                           *kernel_, bodyNames_, wantEnergy, status.strainEnergy, externalWork_,
                           contactWork_};
        for (auto& object : functionObjects_)
        {
            object->execute(state);
        }
        if (wantEnergy)
        {
            double kinetic = 0.0;
            for (std::size_t a = 0; a < n; ++a)
            {
                kinetic += 0.5 * particles_.m[a] * velocitySync_[a].squaredNorm();
            }
            const double total = kinetic + status.strainEnergy - externalWork_ - contactWork_;
            if (!haveInitialEnergy_)
            {
                initialEnergy_ = total;
                haveInitialEnergy_ = true;
            }
            if (progress)
            {
                const double scale = std::abs(initialEnergy_) > 0.0 ? std::abs(initialEnergy_) : 1.0;
                log.progress(step_, step_ - firstStep, time_, deltaT_,
                             (total - initialEnergy_) / scale, true);
            }
        }
        if (outputDue)
        {
            const auto outputStart = std::chrono::steady_clock::now();
            writeOutput(true, step_, time_, functionState);
            log.addOutputSeconds(
                std::chrono::duration<double>(std::chrono::steady_clock::now() - outputStart).count());
            while (nextOutputTime_ <= time_ + 1e-6 * deltaT_)
            {
                nextOutputTime_ += control_.writeInterval;
            }
        }
        lastGoodStep_ = step_;
        lastGoodTime_ = time_;
        if (last)
        {
            break;
        }

        // 7. Advance: v^{n+1/2} = v^{n-1/2} + ½(Δt_{n-1} + Δt_n) a^n (v^{1/2} = v^0 + ½Δt_0 a^0),
        //    x^{n+1} = x^n + Δt v^{n+1/2}; fixed particles stay.
        const double kick = halfStepVelocity_ ? 0.5 * (previousDeltaT_ + dt) : 0.5 * dt;
#pragma omp parallel for schedule(static) if (useThreads(n))
        for (std::size_t a = 0; a < n; ++a)
        {
            previousX_[a] = particles_.x[a];
            if (particles_.fixed[a])
            {
                particles_.v[a].setZero();
                continue;
            }
            particles_.v[a] += kick * acceleration_[a];
            particles_.x[a] += dt * particles_.v[a];
        }
        if (!gravity_.isZero())
        {
            double work = 0.0; // a serial sum: the same for any number of threads
            for (std::size_t a = 0; a < n; ++a)
            {
                work += particles_.m[a] * gravity_.dot(particles_.x[a] - previousX_[a]);
            }
            externalWork_ += work;
        }
        halfStepVelocity_ = true;
        previousDeltaT_ = dt;

        // 8. Contact acts on v^{n+1/2} at x^{n+1} (spec §9, §12).
        if (contact_->active())
        {
            ContactState<D> contactState{particles_.x, particles_.v, particles_, dt};
            contact_->apply(contactState, contactDeltaV_);
            double work = 0.0; // Σ m Δv·(v_before + ½Δv) with v_before = v_after - Δv
            for (std::size_t a = 0; a < n; ++a)
            {
                work += particles_.m[a] * contactDeltaV_[a].dot(particles_.v[a] - 0.5 * contactDeltaV_[a]);
            }
            contactWork_ += work;
            contactWorkPending_ = true;
            contactDeltaT_ = dt;
        }

        // 9. Particles must not pass each other along a bar.
        if (const long crossed = crossingParticle(); crossed >= 0)
        {
            const ForceStatus crossing =
                ForceStatus::failed(FailureKind::particleCrossing, crossed, 0.0,
                                    "particle order (it passed its neighbour)");
            time_ += dt;
            ++step_;
            fail(crossing, "after moving the particles");
        }
        time_ += dt;
        ++step_;
    }
}

template class Simulation<1>;
template class Simulation<2>;
template class Simulation<3>;

} // namespace sph
