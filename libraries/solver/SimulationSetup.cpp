// Building a Simulation from the case: particles, bodies (materials, initial velocities,
// constraints), every selected model, the function objects and the reference configuration.
#include "core/Format.hpp"
#include "solver/Simulation.hpp"

#include "core/InputError.hpp"
#include "core/Suggest.hpp"
#include "initialConditions/fields/Fields.hpp"
#include "initialConditions/regions/Region.hpp"

#include <algorithm>
#include <numeric>
#include <sstream>

namespace sph
{

namespace
{

Schema bodySchema()
{
    return Schema()
        .add(Key::dict("material", "the body's material { type ...; rho ...; ... }")
                 .selects("material"))
        .add(Key::vector("velocity", "initial velocity of the whole body [m/s]").defaultValue("0"))
        .add(Key::dict("initialVelocity", "initial velocities by region: name { region { ... }; "
                                          "type ...; ... }, applied in order after 'velocity'")
                 .selects("velocityField")
                 .optional())
        .add(Key::dict("initialDisplacement", "initial displacements x = X + u by region: name { "
                                              "region { ... }; type ...; ... }, added in order")
                 .selects("displacementField")
                 .optional())
        .add(Key::dict("constraints", "fixed particles by region: name { type fixed; region { "
                                      "... }; }")
                 .optional())
        .add(Key::dict("initialStress", "the stress at t = 0 { type geostatic; ... } (plastic "
                                        "materials: stored as an initial elastic strain)")
                 .selects("stressField")
                 .optional());
}

Schema constraintSchema()
{
    return Schema()
        .add(Key::word("type", "fixed: position held, velocity zero").choices({"fixed"}))
        .add(Key::dict("region", "which particles, by initial position { type ...; ... }")
                 .selects("region"));
}

// A field or constraint entry reads its `region { ... }` besides the model's own keys.
Selection withRegion(std::string defaultType = "")
{
    return {std::move(defaultType),
            Schema().add(Key::dict("region", "which particles, by initial position { type ...; ... }")
                             .selects("region"))};
}

} // namespace

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
    scheme_ = selectModel<Stabilisation<D>>(*schemes.stabilisation, {kernel_.get(), &fields_}, D);
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

    setupBodies(dicts.get("bodies"));
    setupWalls();
    setupViscosity(schemes);
    checkCrossingOrder();
    setupFunctionObjects();

    reference_ = std::make_unique<ReferenceManager<D>>(*formulation_, *scheme_, *kernel_);
    const ForceStatus status = reference_->initialise(particles_);
    if (!status.ok())
    {
        const Entry* hOverDx = schemes.kernel->find("hOverDx");
        throw InputError(hOverDx ? hOverDx->valueLocation() : schemes.kernel->location(),
                         particleName(static_cast<std::size_t>(status.badParticle)) +
                             " has too few neighbours: its " + status.message +
                             " is singular in the initial configuration",
                         {"Increase hOverDx (now " + std::to_string(kernel_->hOverDx()) +
                              ") or check the geometry in system/particlesDict (isolated "
                              "particles, bodies thinner than two spacings).",
                          "Open constant/particles.vtu in ParaView to see the particles."});
    }

    const std::size_t n = particles_.size();
    acceleration_.assign(n, Vec<D>::Zero());
    velocitySync_ = particles_.v;
    previousX_ = particles_.x;
    if (contact_->active())
    {
        contactDeltaV_.assign(n, Vec<D>::Zero());
    }
    nextF_.assign(n, Mat<D>::Identity());
    nextP_.assign(n, Mat<D>::Zero());
    declareFields();
}

template <int D>
Simulation<D>::~Simulation() = default;

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
void Simulation<D>::setInitialStress(const Dictionary& dict, std::size_t b)
{
    Material<D>& material = *materialModels_[b];
    const BodyRange& range = particles_.bodies[b];
    const auto field = selectModel<StressField<D>>(
        dict,
        {gravity_, material.density(), material.atRestCoefficient(), &particles_.X,
         &particles_.V0, range.begin, range.end},
        D);
    for (std::size_t a = range.begin; a < range.end; ++a)
    {
        const Eigen::Matrix3d sigma = field->stress(a);
        switch (material.startFromStress(a, sigma))
        {
        case Material<D>::InitialStress::set:
            break;
        case Material<D>::InitialStress::notSupported:
            throw InputError(dict.location(),
                             "body '" + bodyNames_[b] + "': its material cannot start from a "
                             "stress (it keeps no history to hold an initial elastic strain)",
                             {"Plastic materials can: hencky's plastic counterparts j2Plasticity "
                              "and druckerPrager (a large yieldStress or cohesion keeps them "
                              "elastic)."});
        case Material<D>::InitialStress::outsideYieldSurface:
            throw InputError(dict.location(),
                             "body '" + bodyNames_[b] + "': the initial stress at " +
                                 particleName(a) + " is outside the material's yield surface "
                                 "(sigma_xx " + formatNumber(sigma(0, 0)) + ", sigma_yy " +
                                 formatNumber(sigma(1 % 3, 1 % 3)) + ", sigma_zz " +
                                 formatNumber(sigma(2, 2)) + " Pa)",
                             {"For geostatic: a K0 nearer 1 (the default 1 - sin(phi) of "
                              "druckerPrager is inside its cone)."});
        }
    }
}

template <int D>
void Simulation<D>::setupBodies(const Dictionary& bodies)
{
    // Every body of the particle file needs a dictionary here, and vice versa.
    for (const Entry& entry : bodies.entries())
    {
        // `gravity`, and definitions copied elsewhere with $name, are not bodies.
        if (entry.key() == "gravity" || entry.referenced())
        {
            continue;
        }
        if (std::find(bodyNames_.begin(), bodyNames_.end(), entry.key()) == bodyNames_.end())
        {
            std::vector<std::string> notes{"Bodies in constant/particles.vtu: " +
                                           joinSorted(bodyNames_)};
            const std::string hint = didYouMean(entry.key(), bodyNames_);
            notes.push_back(hint.empty() ? "After editing system/particlesDict, run sphParticles "
                                           "again."
                                         : hint);
            throw InputError(entry.keyLocation(),
                             "constant/bodies names a body '" + entry.key() +
                                 "' that the particles do not have",
                             notes);
        }
    }
    if (const Entry* gravity = bodies.find("gravity"))
    {
        Dictionary only("", bodies.location());
        only.add(*gravity);
        const Params p = Schema()
                             .add(Key::vector("gravity", "body-force acceleration [m/s^2]"))
                             .validate(only, "constant/bodies", D);
        gravity_ = toVec<D>(p.vector("gravity"));
    }
    for (std::size_t b = 0; b < bodyNames_.size(); ++b)
    {
        const Entry* entry = bodies.find(bodyNames_[b]);
        if (!entry || !entry->isDict())
        {
            throw InputError(entry ? entry->keyLocation() : bodies.location(),
                             "missing the body '" + bodyNames_[b] +
                                 "' (it is in constant/particles.vtu, from system/particlesDict)",
                             {"Every body needs its material here: " + bodyNames_[b] +
                              " { material { type ...; } }"});
        }
        const Dictionary& dict = entry->dict();
        const Params p = bodySchema().validate(dict, "a body", D, TypeEntry::isKey);
        materialModels_.push_back(selectModel<Material<D>>(
            p.dict("material"), {&fields_, particles_.bodies[b], &particles_.F}, D));
        materials_.push_back(materialModels_.back().get());
        historyMaterials_ = historyMaterials_ || materials_.back()->hasHistory();
        const BodyRange& range = particles_.bodies[b];
        if (p.has("initialStress"))
        {
            setInitialStress(p.dict("initialStress"), b);
        }
        const Vec<D> velocity = toVec<D>(p.vector("velocity"));
        for (std::size_t a = range.begin; a < range.end; ++a)
        {
            particles_.m[a] = materials_[b]->density() * particles_.V0[a];
            particles_.v[a] = velocity;
        }
        // The particles of this body in the (validated) `region { ... }` of `owner`.
        const auto selected = [&](const Dictionary& owner) {
            const auto region = selectModel<Region<D>>(owner.find("region")->dict(), {}, D);
            const auto chosen = region->select(particles_.X, range.begin, range.end);
            if (chosen.empty())
            {
                throw InputError(owner.location(),
                                 "'" + owner.displayName() + "' selects no particle of body '" +
                                     bodyNames_[b] + "'",
                                 {"Regions test the initial positions; open "
                                  "constant/particles.vtu in ParaView to check the region."});
            }
            return chosen;
        };
        if (p.has("initialDisplacement"))
        {
            for (const Entry& item : p.dict("initialDisplacement").entries())
            {
                if (!item.isDict())
                {
                    throw InputError(item.keyLocation(), "'" + item.key() +
                                                             "' in initialDisplacement must be a "
                                                             "dictionary { region { ... }; type "
                                                             "...; }");
                }
                const auto field =
                    selectModel<DisplacementField<D>>(item.dict(), {}, D, withRegion());
                for (const std::size_t a : selected(item.dict()))
                {
                    particles_.x[a] += field->displacement(particles_.X[a], a);
                }
            }
        }
        if (p.has("initialVelocity"))
        {
            for (const Entry& item : p.dict("initialVelocity").entries())
            {
                if (!item.isDict())
                {
                    throw InputError(item.keyLocation(), "'" + item.key() +
                                                             "' in initialVelocity must be a "
                                                             "dictionary { region { ... }; "
                                                             "velocity (...); }");
                }
                const auto field =
                    selectModel<VelocityField<D>>(item.dict(), {}, D, withRegion("uniform"));
                for (const std::size_t a : selected(item.dict()))
                {
                    particles_.v[a] = field->velocity(particles_.X[a]);
                }
            }
        }
        if (p.has("constraints"))
        {
            for (const Entry& item : p.dict("constraints").entries())
            {
                if (!item.isDict())
                {
                    throw InputError(item.keyLocation(), "'" + item.key() +
                                                             "' in constraints must be a "
                                                             "dictionary { type fixed; region { "
                                                             "... }; }");
                }
                constraintSchema().validate(item.dict(), "a constraint", D, TypeEntry::isKey);
                for (const std::size_t a : selected(item.dict()))
                {
                    particles_.fixed[a] = 1;
                    particles_.v[a].setZero();
                }
            }
        }
    }
}

// The walls of constant/walls, and the bound of their stiffness on the time step: a particle
// against a wall oscillates at ω = c0/s, so ω Δt <= courant hOverDx (walls/WallSet.hpp).
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

template <int D>
void Simulation<D>::checkCrossingOrder()
{
    if constexpr (D == 1)
    {
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
        typename FunctionObject<D>::Args args;
        args.name = entry.key();
        args.caseDir = dicts_.caseDir();
        args.initial = &particles_;
        args.materials = &materials_;
        args.bodyNames = &bodyNames_;
        args.fields = &fields_;
        args.wallNames = &walls_->names();
        args.artificialViscosity = viscosity_->active();
        functionObjects_.push_back(selectModel<FunctionObject<D>>(
            entry.dict(), args, D, Selection::withBodies(bodyNames_)));
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
