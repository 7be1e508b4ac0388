// The step from the forces' measured largest frequency (docs/theory/timeStep.md): what the
// solver gives the time integrator's probe (forces at perturbed positions, the level restored)
// and what it refuses beside it.
#include "solver/Simulation.hpp"

#include "core/InputError.hpp"

namespace sph
{

// stepBound operator measures the internal forces only (docs/theory/timeStep.md §T4): what acts
// besides them with a stiffness of its own is refused, the walls' bound is kept as a cap.
template <int D>
void Simulation<D>::setupOperatorProbe()
{
    const std::optional<OperatorProbeRequest> request = integrator_->operatorProbe();
    if (!request)
    {
        return;
    }
    const auto refuse = [&request](const std::string& what, const std::string& hint) {
        throw InputError(request->where,
                         "stepBound operator measures the internal forces only; " + what,
                         {hint, "stepBound waveSpeed (the default) runs it; 'probeInterval N;' "
                                "with waveSpeed reports omega dt (docs/theory/timeStep.md §T4)."});
    };
    integrator_->setOperatorFrequency(
        [this](int iterations, std::vector<Vec<D>>& mode) { return probeOperator(iterations, mode); });
    if (!request->controlsStep)
    {
        return; // it only reports
    }
    if (viscosity_->active())
    {
        refuse("an artificial viscosity bounds the step by its own signal speed",
               "Remove artificialViscosity from system/sphSchemes.");
    }
    if (contact_->active())
    {
        refuse("the contact between bodies has a stiffness of its own",
               "Use one body, or contact { type none; }.");
    }
    // updateDue(1, 0, 0): a move is due one step after the last without any strain, i.e.
    // before every evaluation (referenceUpdateInterval 1); with a longer interval, or moves by
    // strain, the scheme's force acts between moves and the probe measures a stiffness that is
    // there.
    const bool movesEveryStep =
        formulation_->updatesReference() && formulation_->updateDue(1, 0, 0.0);
    if (scheme_->vanishesAtReference() && movesEveryStep)
    {
        // Measured on the column collapse at 5 mm: 420 000 steps against updatedLagrangian
        // none's 10 000, for the same motion to every digit.
        refuse("with the reference moved before every evaluation the stabilisation's force is "
               "zero wherever the forces are evaluated, but the probe's perturbed positions "
               "feel its stiffness, so the measured step would be far smaller than the motion "
               "needs",
               "updatedLagrangian with hourglass moves as updatedLagrangian with none to every "
               "digit: use stabilisation none, or formulation totalLagrangian.");
    }
    if (!walls_->empty())
    {
        double c0 = 0.0;
        for (const auto& material : materialModels_)
        {
            c0 = std::max(c0, material->waveSpeed(Mat<D>::Identity()));
        }
        wallDeltaT_ = control_.courant * kernel_->h() / c0;
    }
}

// Power iterations on the forces at perturbed positions about x^n, whose force T(x^n) is in
// acceleration_ (before accelerate()); then the level's F, P and forces are put back, with what
// the scheme set aside for the commit. A scheme that cannot set its evaluation aside gets the
// level's own evaluation once more instead, so that its scratch state is the level's again,
// bit for bit (each evaluation is a function of the positions and the committed state only).
template <int D>
typename OperatorProbe<D>::Result Simulation<D>::probeOperator(int iterations,
                                                               std::vector<Vec<D>>& mode)
{
    const std::vector<Vec<D>> x = particles_.x;
    const std::vector<Vec<D>> T = acceleration_;
    const bool setAside = scheme_->setAsideEvaluation();
    std::vector<Mat<D>> levelF;
    std::vector<Mat<D>> levelP;
    if (setAside)
    {
        levelF = particles_.F; // with the ghosts' (refreshed by the level's evaluation)
        levelP = particles_.P;
    }
    const auto forcesAt = [this](const std::vector<Vec<D>>& perturbed, std::vector<Vec<D>>& forces) {
        particles_.x = perturbed;
        computeForces(false, false);
        forces = acceleration_;
    };
    const typename OperatorProbe<D>::Result result = OperatorProbe<D>::run(
        {x, T, particles_.m, particles_.fixed, kernel_->h(), step_, ranks_}, forcesAt, iterations,
        mode);
    particles_.x = x;
    if (setAside)
    {
        particles_.F.swap(levelF);
        particles_.P.swap(levelP);
        acceleration_ = T;
        scheme_->restoreEvaluation();
    }
    else
    {
        computeForces(levelAtReference_, levelWantsEnergy_);
    }
    return result;
}

template class Simulation<1>;
template class Simulation<2>;
template class Simulation<3>;

} // namespace sph
