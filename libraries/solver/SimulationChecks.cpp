// What bounds and what stops a run: the wave-speed bound of the time step, the 1D order check
// and the diagnosis of a numerical failure (with the last good level written).
#include "solver/Simulation.hpp"

#include "core/Application.hpp"
#include "core/Format.hpp"
#include "core/InputError.hpp"
#include "particles/Parallel.hpp"

#include <iomanip>
#include <sstream>

namespace sph
{

// The largest wave speed of particles first .. first + n of body b as the forces see it: in
// an updated-Lagrangian run, with the stretch since the reference moved (theory (P2.6)).
template <int D>
double Simulation<D>::waveSpeedOf(std::size_t b, std::size_t first, std::size_t n) const
{
    if (formulation_->updatesReference())
    {
        return materials_[b]->maxWaveSpeedSinceReference(
            &particles_.F[first], &reference_->reference().F[first], n, first);
    }
    return materials_[b]->maxWaveSpeed(&particles_.F[first], n, first);
}

template <int D>
WaveSpeedBound Simulation<D>::waveSpeedBound() const
{
    // Per body, in chunks, in parallel: a maximum does not depend on the order.
    const auto bodyMaximum = [this](std::size_t b) {
        const BodyRange& range = particles_.bodies[b];
        const std::size_t chunk = 1024;
        const long chunks = static_cast<long>((range.size() + chunk - 1) / chunk);
        double c = 0.0;
#pragma omp parallel for schedule(static) reduction(max : c) if (useThreads(range.size()))
        for (long i = 0; i < chunks; ++i)
        {
            const std::size_t first = range.begin + static_cast<std::size_t>(i) * chunk;
            const std::size_t count = std::min(chunk, range.end - first);
            c = std::max(c, waveSpeedOf(b, first, count));
        }
        return c;
    };
    const auto fastestBody = [this, bodyMaximum] {
        double c = 0.0;
        std::size_t body = 0;
        for (std::size_t b = 0; b < particles_.bodies.size(); ++b)
        {
            if (const double bodyC = bodyMaximum(b); bodyC > c)
            {
                c = bodyC;
                body = b;
            }
        }
        return std::pair<double, std::size_t>{c, body};
    };
    // Only a collapse needs the fastest particle itself.
    const auto fastestParticle = [this, fastestBody] {
        const std::size_t body = fastestBody().second;
        const BodyRange& range = particles_.bodies[body];
        std::size_t fastest = range.begin;
        double best = -1.0;
        for (std::size_t a = range.begin; a < range.end; ++a)
        {
            const double ca = waveSpeedOf(body, a, 1);
            if (!(ca <= best))
            {
                best = ca;
                fastest = a;
            }
        }
        return fastest;
    };
    // An artificial viscosity raises the speed that bounds the step (Monaghan 1992, §10).
    return {kernel_->h(),
            [this, fastestBody] {
                // Distributed: the fastest of every rank (exact: a maximum), so every rank
                // takes the serial run's step.
                return comm_.maximum(viscosity_->signalSpeed(fastestBody().first));
            },
            fastestParticle, wallDeltaT_};
}

// A run that would take more than 1e12 steps, or write more than once per step, is an input
// error (such values otherwise run for ever with no output).
template <int D>
void Simulation<D>::checkRunLength(double deltaT) const
{
    outputSchedule_.checkStep(deltaT);
    const double steps = (control_.endTime - time_) / deltaT;
    if (steps > 1e12)
    {
        throw InputError(dicts_.get("controlDict").find("endTime")->valueLocation(),
                         "the run to endTime " + formatNumber(control_.endTime) +
                             " s would take " + formatNumber(steps) + " steps of " +
                             formatNumber(deltaT) + " s",
                         {"The time step is courant h / c, c the largest wave speed of the "
                          "materials: check endTime, E and rho."});
    }
}

template <int D>
long Simulation<D>::crossingParticle() const
{
    if constexpr (D == 1)
    {
        // A distributed run checks its local particles (the ghosts' x are their owners') and
        // reports a crossing at an owned particle; the ranks agree on the least global index,
        // the serial run's first crossing along the bar when the ids follow the bar.
        for (const auto& order : barOrder_)
        {
            for (std::size_t i = 1; i < order.size(); ++i)
            {
                if (!(particles_.x[order[i]][0] > particles_.x[order[i - 1]][0]) &&
                    (!distributed() || owned_[order[i]]))
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
    checkStatus(status, when);
    throw std::logic_error("Simulation::fail called with a good state");
}

template <int D>
std::string Simulation<D>::describeFailure(const ForceStatus& status, const std::string& when) const
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
    return message.str();
}

template <int D>
void Simulation<D>::failWith(const std::string& diagnosis)
{
    std::string written;
    if (lastGood_.step >= 0)
    {
        writeOutput(lastGood_, {});
        written = "The last good state (step " + std::to_string(lastGood_.step) + ", t = " +
                  std::to_string(lastGood_.time) + " s) is written to " + lastOutputFile_ +
                  " (listed in VTK/" + caseName_ + ".pvd).";
    }
    // What to try depends on what runs: a scheme never suggests itself, nor the step bound.
    const std::string next = scheme_->nextToTry(formulation_->updatesReference(), historyMaterials_);
    const auto probe = integrator_->operatorProbe();
    std::string step = "lower courant";
    if (probe && probe->controlsStep)
    {
        step += "; the step already follows the forces' measured largest frequency";
    }
    else if (!viscosity_->active() && !contact_->active())
    {
        step += ", or let the step follow the forces' measured largest frequency: "
                "timeIntegration { stepBound operator; } (docs/theory/timeStep.md)";
    }
    throw NumericalFailure(diagnosis + "\n" + written + "\nLikely causes: " +
                           (next.empty() ? std::string()
                                         : "the scheme is unstable for this problem (try " + next +
                                               "), ") +
                           "the time step is too large (" + step + "), the spacing too coarse "
                           "for the deformation, or the deformation is beyond the material "
                           "model." + energyGrowthNote());
}

// A run whose energy grew before it failed, with moves of the reference and the kick across
// them as one: the kicks can have fed it (gradF-plastic.md §G19-§G20). The growth is the fact;
// the cause is a suggestion, so the note says both.
template <int D>
std::string Simulation<D>::energyGrowthNote() const
{
    constexpr double noticeable = 0.05; // the smallest growth worth a remark
    if (!lastDrift_ || !(lastDrift_->second > noticeable) || !formulation_->updatesReference() ||
        splitKick_)
    {
        return "";
    }
    std::ostringstream note;
    const double percent = 100.0 * lastDrift_->second;
    note << "\nThe energy had grown by " << std::fixed << std::setprecision(percent < 10.0 ? 1 : 0)
         << percent << " % of the initial by t = " << std::defaultfloat << std::setprecision(6)
         << lastDrift_->first
         << " s. With the reference moving, the kicks across its moves can feed it: try "
            "formulation { type updatedLagrangian; splitKick yes; } (with gradF's "
            "plasticSamples elasticState, also moveWeights conserving; "
            "docs/theory/gradF-plastic.md §G20).";
    return note.str();
}

template <int D>
std::string Simulation<D>::particleName(std::size_t a) const
{
    std::ostringstream out;
    out << "particle " << (a < particles_.size() ? globalIndex(a) : static_cast<long>(a));
    if (a < particles_.size())
    {
        out << " (body '" << bodyNames_[static_cast<std::size_t>(particles_.body[a])]
            << "', initial position (" << particles_.X[a].transpose() << "))";
    }
    return out.str();
}

template class Simulation<1>;
template class Simulation<2>;
template class Simulation<3>;

} // namespace sph
