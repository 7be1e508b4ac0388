// Building the bodies of a Simulation from constant/bodies: gravity, each body's material, its
// initial stress, initial displacements and velocities by region, and fixed particles.
#include "solver/Simulation.hpp"

#include "core/Format.hpp"
#include "core/InputError.hpp"
#include "core/Suggest.hpp"
#include "initialConditions/fields/Fields.hpp"
#include "initialConditions/regions/Region.hpp"

#include <algorithm>

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
void Simulation<D>::setInitialStress(const Dictionary& dict, std::size_t b)
{
    Material<D>& material = *materialModels_[b];
    const BodyRange& range = particles_.bodies[b];
    const auto field = selectModel<StressField<D>>(
        dict,
        {gravity_, material.density(), material.atRestCoefficient(), &particles_.X,
         &particles_.V0, range.begin, range.end},
        D);
    // A body at rest holds its initial stress with a small elastic strain: a stress of the order
    // of E or above (K0 1e300 passed -dryRun and failed at step 0 blaming the scheme; issue 31)
    // is no state at rest.
    constexpr double largestStrain = 1.0;
    for (std::size_t a = range.begin; a < range.end; ++a)
    {
        const Eigen::Matrix3d sigma = field->stress(a);
        const double strain = sigma.cwiseAbs().maxCoeff() / material.youngsModulus();
        if (!(strain <= largestStrain))
        {
            throw InputError(dict.location(),
                             "body '" + bodyNames_[b] + "': the initial stress at " +
                                 particleName(a) + " (sigma_xx " + formatNumber(sigma(0, 0)) +
                                 ", sigma_yy " + formatNumber(sigma(1 % 3, 1 % 3)) +
                                 ", sigma_zz " + formatNumber(sigma(2, 2)) + " Pa) is " +
                                 formatNumber(strain) + " times the Young's modulus E = " +
                                 formatNumber(material.youngsModulus()) +
                                 " Pa: no body at rest holds it",
                             {"For geostatic: K0 is the horizontal over the vertical stress, "
                              "of order 1 (0.5 for a sand at rest; the default of druckerPrager "
                              "is 1 - sin(phi)).",
                              "Are E, rho and gravity in Pa, kg/m^3 and m/s^2?"});
        }
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

// A body's material makes its own time step courant h / c: one longer than the whole run
// means a wave speed far below any solid's (E 1e-300 was reported against writeInterval at
// step 0; issue 31), an input error at the material, -dryRun included.
template <int D>
void Simulation<D>::checkWaveSpeed(const Dictionary& material, std::size_t b) const
{
    const double c = materials_[b]->waveSpeed(Mat<D>::Identity());
    const double step = control_.courant * kernel_->h() / c;
    if (step <= control_.endTime)
    {
        return;
    }
    throw InputError(material.location(),
                     "body '" + bodyNames_[b] + "': its material's wave speed c = " +
                         formatNumber(c) + " m/s makes a time step courant h / c = " +
                         formatNumber(step) + " s, longer than the whole run (endTime " +
                         formatNumber(control_.endTime) + " s)",
                     {"c = sqrt(stiffness / rho): " + materials_[b]->summary() + ".",
                      "Are E (or mu, kappa) in Pa and rho in kg/m^3? Steel: E 200e9, rho 7800; "
                      "a soil: E 10e6, rho 2000."});
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
            p.dict("material"), {&fields_, particles_.bodies[b], &particles_.F, scheme_->evaluatesParticles()}, D));
        materials_.push_back(materialModels_.back().get());
        checkWaveSpeed(p.dict("material"), b);
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
template class Simulation<1>;
template class Simulation<2>;
template class Simulation<3>;

} // namespace sph
