// Building a Simulation from the case: particles, every selected model, the function objects
// and the reference configuration (the bodies: SimulationBodies.cpp).
#include "core/Format.hpp"
#include "solver/Simulation.hpp"

#include "core/InputError.hpp"
#include "core/PlainName.hpp"
#include "core/Suggest.hpp"
#include "initialConditions/fields/Fields.hpp"
#include "initialConditions/regions/Region.hpp"

#include <algorithm>
#include <numeric>
#include <sstream>

namespace sph
{


template <int D>
Simulation<D>::Simulation(const CaseDictionaries& dicts, const ControlSettings& control,
                          const SchemeSettings& schemes, const InitialParticles& initial)
    : dicts_(dicts), control_(control), caseName_(dicts.caseName()),
      outputSchedule_(control.writeControl == WriteControl::timeStep ? 0.0 : control.writeInterval,
                      dicts.get("controlDict").find("writeInterval")->valueLocation()),
      pvd_(dicts.caseDir() / "VTK" / (dicts.caseName() + ".pvd"))
{
    if (initial.dimension != D)
    {
        throw InputError(dicts.get("sphSchemes").find("dimension")->valueLocation(),
                         "the case is " + std::to_string(D) + "D but constant/particles.vtu holds " +
                             std::to_string(initial.dimension) + "D particles",
                         {"Run sphParticles again after changing 'dimension'."});
    }
    spacing_ = initial.spacing;
    loadParticles(initial);

    kernel_ = selectModel<Kernel>(*schemes.kernel, Kernel::Args{D, spacing_}, D);
    formulation_ = selectModel<Formulation<D>>(*schemes.formulation, {}, D);
    scheme_ = selectModel<Stabilisation<D>>(
        *schemes.stabilisation, {kernel_.get(), &fields_, formulation_->updatesReference()}, D);
    const typename Contact<D>::Args contactArgs{kernel_.get(), bodyNames_};
    if (schemes.contact)
    {
        contact_ = selectModel<Contact<D>>(*schemes.contact, contactArgs, D,
                                           Selection::withBodies(bodyNames_));
    }
    else
    {
        const Dictionary none("contact", dicts.get("sphSchemes").location());
        contact_ = createModel<Contact<D>>("none", none, contactArgs, D);
    }

    const Dictionary leapfrog("timeIntegration", dicts.get("sphSchemes").location());
    integrator_ = selectModel<TimeIntegration<D>>(
        schemes.timeIntegration ? *schemes.timeIntegration : leapfrog,
        {control.courant, control.timeStepUpdateInterval}, D, {"leapfrog", {}});
    if (integrator_->kineticDamping())
    {
        damping_.emplace();
    }
    splitKick_ = formulation_->splitsKickAtMoves();
    if (splitKick_ && !integrator_->splitsKicks())
    {
        throw InputError(schemes.formulation->find("splitKick")->valueLocation(),
                         "splitKick needs a time integrator whose kick can be split at a level; '" +
                             integrator_->typeName() + "' cannot",
                         {"Use timeIntegration { type leapfrog; } (the default), or splitKick no."});
    }

    setupBodies(dicts.get("bodies"));
    setupWalls();
    setupViscosity(schemes);
    setupImpenetrability(schemes);
    setupOperatorProbe();
    checkCrossingOrder();
    setupFunctionObjects();

    std::vector<Material<D>*> materials;
    for (const auto& material : materialModels_)
    {
        materials.push_back(material.get());
    }
    reference_ = std::make_unique<ReferenceManager<D>>(*formulation_, *scheme_, *kernel_, materials);
    const Entry* hOverDx = schemes.kernel->find("hOverDx");
    kernelLocation_ = hOverDx ? hOverDx->valueLocation() : schemes.kernel->location();
    if (comm_.parallel())
    {
        // A distributed run builds the neighbourhoods of each rank's share only, when it has
        // one (distribute()): every rank holds the whole set until then, but not the pairs of
        // the whole set, which are most of its memory.
        reference_->setInitial(particles_);
    }
    else
    {
        const ForceStatus status = reference_->initialise(particles_);
        if (!status.ok())
        {
            throw tooFewNeighbours(particleName(static_cast<std::size_t>(status.badParticle)),
                                   status.message);
        }
    }

    const std::size_t n = particles_.size();
    acceleration_.assign(n, Vec<D>::Zero());
    velocitySync_ = particles_.v;
    previousX_ = particles_.x;
    if (contact_->active())
    {
        contactDeltaV_.assign(n, Vec<D>::Zero());
    }
    if (damping_)
    {
        dampingDeltaV_.assign(n, Vec<D>::Zero());
    }
    nextF_.assign(n, Mat<D>::Identity());
    nextP_.assign(n, Mat<D>::Zero());
    declareFields();
}

template <int D>
Simulation<D>::~Simulation() = default;

template <int D>
InputError Simulation<D>::tooFewNeighbours(const std::string& particle, const std::string& what) const
{
    return InputError(kernelLocation_,
                      particle + " has too few neighbours: its " + what +
                          " is singular in the initial configuration",
                      {"Increase hOverDx (now " + std::to_string(kernel_->hOverDx()) +
                           ") or check the geometry in system/particlesDict (isolated "
                           "particles, bodies thinner than two spacings).",
                       "Open constant/particles.vtu in ParaView to see the particles."});
}

template <int D>
void Simulation<D>::loadParticles(const InitialParticles& initial)
{
    const std::size_t n = initial.size();
    particles_.resize(n);
    fields_.setSize(n);
    bodyNames_ = initial.bodyNames;
    for (std::size_t a = 0; a < n; ++a)
    {
        for (int d = 0; d < D; ++d)
        {
            particles_.X[a][d] = initial.X[3 * a + static_cast<std::size_t>(d)];
        }
        particles_.x[a] = particles_.X[a];
        particles_.V0[a] = initial.V[a];
        particles_.body[a] = initial.body[a];
        if (!(initial.V[a] > 0.0) || !particles_.X[a].allFinite())
        {
            throw InputError("particle " + std::to_string(a) + " in constant/particles.vtu has "
                             "volume " + std::to_string(initial.V[a]) + " or a non-finite position",
                             {"Volumes must be positive; run sphParticles again."});
        }
    }
    // Each body is one contiguous range (sphParticles writes them so).
    for (std::size_t b = 0; b < bodyNames_.size(); ++b)
    {
        const auto first = std::find(initial.body.begin(), initial.body.end(), static_cast<int>(b));
        const auto last = std::find_if(first, initial.body.end(),
                                       [&](int id) { return id != static_cast<int>(b); });
        if (first == initial.body.end() ||
            std::find(last, initial.body.end(), static_cast<int>(b)) != initial.body.end())
        {
            throw InputError("body '" + bodyNames_[b] + "' in constant/particles.vtu is empty or "
                             "not contiguous",
                             {"Run sphParticles again."});
        }
        particles_.bodies.push_back({bodyNames_[b],
                                     static_cast<std::size_t>(first - initial.body.begin()),
                                     static_cast<std::size_t>(last - initial.body.begin())});
    }
}

template <int D>
void Simulation<D>::setupWalls()
{
    walls_ = std::make_unique<WallSet<D>>(dicts_.has("walls") ? &dicts_.get("walls") : nullptr,
                                          bodyNames_, materials_, spacing_);
    const double omegaDeltaT = control_.courant * kernel_->hOverDx();
    if (!walls_->empty() && omegaDeltaT >= 1.0)
    {
        throw InputError(dicts_.get("controlDict").find("courant")->valueLocation(),
                         "with walls, courant x hOverDx (the bound of omega dt of a particle "
                         "against a wall) must be below 1; it is " + formatNumber(omegaDeltaT),
                         {"Lower courant below " + formatNumber(1.0 / kernel_->hOverDx()) +
                          ": the walls are as stiff as the material (constant/walls)."});
    }
}

// After the bodies: the viscosity reads each body's ρ0 and c0. `none` when the entry is absent.
template <int D>
void Simulation<D>::setupViscosity(const SchemeSettings& schemes)
{
    const Dictionary none("artificialViscosity", dicts_.get("sphSchemes").location());
    viscosity_ = selectModel<ArtificialViscosity<D>>(
        schemes.artificialViscosity ? *schemes.artificialViscosity : none,
        {kernel_.get(), materials_}, D, {"none", {}});
    if (viscosity_->active())
    {
        viscousAcceleration_.assign(particles_.size(), Vec<D>::Zero());
    }
}

// After the bodies: the energy reads each body's ρ0 and c0 (docs/theory/impenetrability.md).
template <int D>
void Simulation<D>::setupImpenetrability(const SchemeSettings& schemes)
{
    if (!schemes.impenetrability)
    {
        return;
    }
    const Params p =
        Schema()
            .add(Key::real("distance", "pairs closer than this many initial spacings store "
                                       "energy; 0.5 by the sweeps on the collapse and the "
                                       "metal impact (docs/theory/impenetrability.md §I4); 0: "
                                       "none does (off, as without the key)")
                     .range(0.0, 1.0)
                     .defaultValue("0.5"))
            .validate(*schemes.impenetrability, "impenetrability", D);
    // δ = 0: no pair is ever closer, Π_I = 0; no model, so the run is the one without the key
    // (a case that names it can be switched off from the command line or a study level).
    if (p.real("distance") > 0.0)
    {
        impenetrability_ = std::make_unique<Impenetrability<D>>(p.real("distance"), materials_);
    }
}

// 1D: each body's particles in the order of X along the bar, which they must keep (a
// distributed run sorts its local particles again whenever they change).
template <int D>
void Simulation<D>::checkCrossingOrder()
{
    if constexpr (D == 1)
    {
        barOrder_.clear();
        for (const BodyRange& range : particles_.bodies)
        {
            std::vector<std::size_t> order(range.size());
            std::iota(order.begin(), order.end(), range.begin);
            std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
                return particles_.X[a][0] < particles_.X[b][0];
            });
            barOrder_.push_back(order);
        }
    }
}

template <int D>
void Simulation<D>::setupFunctionObjects()
{
    if (!control_.functions)
    {
        return;
    }
    for (const Entry& entry : control_.functions->entries())
    {
        if (!entry.isDict())
        {
            throw InputError(entry.keyLocation(),
                             "'" + entry.key() + "' in functions must be a dictionary { type ...; }",
                             {"Valid function object types: " +
                              joinSorted(Registry<FunctionObject<D>>::names())});
        }
        // Its name becomes postProcessing/<name>/ and the names of the files in it.
        requirePlainName(entry, "function object", "folder and file names under postProcessing/");
        typename FunctionObject<D>::Args args;
        args.name = entry.key();
        args.caseDir = dicts_.caseDir();
        args.initial = &particles_;
        args.materials = &materials_;
        args.bodyNames = &bodyNames_;
        args.fields = &fields_;
        args.wallNames = &walls_->names();
        args.artificialViscosity = viscosity_->active();
        args.kineticDamping = damping_.has_value();
        args.endTime = control_.endTime;
        args.totalDeformationGradient = !(formulation_->updatesReference() &&
                                          scheme_->movesParticleHistory() && historyMaterials_);
        args.ranks = &ranks_;
        functionObjects_.push_back(selectModel<FunctionObject<D>>(
            entry.dict(), args, D, Selection::withBodies(bodyNames_)));
        moveEnergyWanted_ = moveEnergyWanted_ || functionObjects_.back()->needsMoveEnergy();
    }
}

template <int D>
std::vector<std::string> Simulation<D>::describe() const
{
    std::vector<std::string> lines;
    std::ostringstream out;
    out << "Case        " << dicts_.caseDir().string() << " (" << caseName_ << "), " << D
        << "D, " << particles_.size() << " particles, spacing " << spacing_ << " m";
    lines.push_back(out.str());
    lines.push_back("Kernel      " + kernel_->summary());
    lines.push_back("Formulation " + formulation_->summary());
    lines.push_back("Scheme      " + scheme_->summary());
    lines.push_back("Contact     " + contact_->summary());
    lines.push_back("Viscosity   " + viscosity_->summary());
    if (impenetrability_)
    {
        lines.push_back("Close pairs impenetrability, energy below " +
                        formatNumber(impenetrability_->distance()) +
                        " initial spacings (docs/theory/impenetrability.md)");
    }
    lines.push_back("Integrator  " + integrator_->summary());
    for (std::size_t b = 0; b < bodyNames_.size(); ++b)
    {
        std::size_t fixed = 0;
        for (std::size_t a = particles_.bodies[b].begin; a < particles_.bodies[b].end; ++a)
        {
            fixed += particles_.fixed[a];
        }
        lines.push_back("Body        " + bodyNames_[b] + ": " +
                        std::to_string(particles_.bodies[b].size()) + " particles (" +
                        std::to_string(fixed) + " fixed), " + materials_[b]->summary());
    }
    for (const auto& wall : walls_->describe())
    {
        lines.push_back("Wall        " + wall);
    }
    if (!walls_->empty())
    {
        lines.push_back("Walls       stiffness rho0 c0^2 V0 / s^2: omega dt <= courant hOverDx = " +
                        formatNumber(control_.courant * kernel_->hOverDx()));
    }
    std::ostringstream time;
    time << "Time        endTime " << control_.endTime << " s, courant " << control_.courant
         << ", writeInterval " << control_.writeInterval << " s, startFrom "
         << (control_.startFromLatest ? "latestTime" : "startTime");
    lines.push_back(time.str());
    for (const auto& object : functionObjects_)
    {
        lines.push_back("Function    " + object->name() + ": " + object->summary());
    }
    return lines;
}

template class Simulation<1>;
template class Simulation<2>;
template class Simulation<3>;

} // namespace sph
