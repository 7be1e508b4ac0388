#include "solver/CaseSettings.hpp"

#include "core/Format.hpp"
#include "core/InputError.hpp"

#include <cmath>
#include "core/LibraryLoader.hpp"

namespace sph
{

Schema ControlSettings::schema()
{
    return Schema()
        .add(Key::real("endTime", "end of the simulation [s]").positive())
        .add(Key::real("courant", "Courant number alpha in dt = alpha h / c (seed eq. 17)")
                 .range(0.0, 2.0, false, true))
        .add(Key::real("writeInterval", "time between VTK outputs [s] (writeControl timeStep: "
                                        "steps)")
                 .positive())
        .add(Key::word("writeControl",
                       "adjustableRunTime: steps shortened to land on every output time; "
                       "runTime: the first level at or after it; timeStep: every writeInterval "
                       "steps")
                 .choices({"adjustableRunTime", "runTime", "timeStep"})
                 .defaultValue("adjustableRunTime"))
        .add(Key::integer("purgeWrite", "keep only the last N VTK outputs, deleting older ones "
                                        "(0: keep all)")
                 .min(0)
                 .defaultValue("0"))
        .add(Key::word("startFrom", "startTime: from startTime (0: the initial state, else the "
                                    "output written at that time); latestTime: from the last "
                                    "output")
                 .choices({"startTime", "latestTime"})
                 .defaultValue("startTime"))
        .add(Key::real("startTime", "with startFrom startTime: 0 starts afresh, a later time "
                                    "continues from the output written at that time [s]")
                 .nonNegative()
                 .defaultValue("0"))
        .add(Key::word("stopAt", "endTime: run to endTime; writeNow: write the current level and "
                                 "stop (read again while running, as OpenFOAM's "
                                 "runTimeModifiable)")
                 .choices({"endTime", "writeNow"})
                 .defaultValue("endTime"))
        .add(Key::integer("timeStepUpdateInterval",
                          "steps between recomputing the wave speed from the current F (0: keep "
                          "the initial time step)")
                 .min(0)
                 .defaultValue("1"))
        .add(Key::integer("maxSteps", "stop after this many time steps").min(1).optional())
        .add(Key::real("maxLoadImbalance",
                       "distributed runs (sphSolid -parallel): the particles are partitioned "
                       "again when a rank holds more than this times the mean (owned and ghost "
                       "particles), checked at each move of an updated-Lagrangian reference")
                 .range(1.0, 1e3, false, true)
                 .defaultValue("1.2"))
        .add(Key::stringList("libs", "extra model libraries to load at start").defaultValue("()"))
        .add(Key::dict("functions", "function objects: name { type ...; }")
                 .selects("functionObject")
                 .optional());
}

ControlSettings ControlSettings::read(const CaseDictionaries& dicts)
{
    const Dictionary& dict = dicts.get("controlDict");
    const Params p = schema().validate(dict, "controlDict", 0, TypeEntry::isKey);
    ControlSettings settings;
    if (const Entry* libs = dict.find("libs"))
    {
        for (const Item& item : libs->items().front().items())
        {
            settings.libraries.emplace_back(item.text(), item.location());
        }
    }
    settings.endTime = p.real("endTime");
    settings.courant = p.real("courant");
    settings.writeInterval = p.real("writeInterval");
    const std::string writeControl = p.word("writeControl");
    settings.writeControl = writeControl == "runTime"    ? WriteControl::runTime
                            : writeControl == "timeStep" ? WriteControl::timeStep
                                                         : WriteControl::adjustableRunTime;
    if (settings.writeControl == WriteControl::timeStep &&
        (settings.writeInterval != std::floor(settings.writeInterval) || settings.writeInterval > 1e15))
    {
        p.fail("writeInterval",
               "writeInterval " + formatNumber(settings.writeInterval) +
                   " is not a whole number of steps (writeControl timeStep)",
               {"With writeControl timeStep, writeInterval counts steps: e.g. writeInterval "
                "100; for an interval in seconds use writeControl adjustableRunTime."});
    }
    settings.purgeWrite = p.integer("purgeWrite");
    settings.startFromLatest = p.word("startFrom") == "latestTime";
    if (!settings.startFromLatest && p.real("startTime") > 0.0)
    {
        settings.startTime = p.real("startTime");
        settings.startTimeLocation = p.location("startTime");
    }
    settings.stopAtWriteNow = p.word("stopAt") == "writeNow";
    settings.timeStepUpdateInterval = p.integer("timeStepUpdateInterval");
    settings.maxLoadImbalance = p.real("maxLoadImbalance");
    if (p.has("maxSteps"))
    {
        settings.maxSteps = p.integer("maxSteps");
    }
    if (p.has("functions"))
    {
        settings.functions = &p.dict("functions");
    }
    return settings;
}

Schema SchemeSettings::schema()
{
    return Schema()
        .add(Key::integer("dimension", "space dimension of the case").range(1, 3))
        .add(Key::dict("kernel", "smoothing kernel { type ...; hOverDx 1.5; }").selects("kernel"))
        .add(Key::dict("formulation", "when the reference configuration moves { type ...; }")
                 .selects("formulation"))
        .add(Key::dict("stabilisation", "internal-force scheme { type ...; }")
                 .selects("stabilisation"))
        .add(Key::dict("contact", "contact between bodies { type ...; }")
                 .selects("contact")
                 .optional())
        .add(Key::dict("timeIntegration", "time integrator { type ...; } (default leapfrog)")
                 .selects("timeIntegration")
                 .optional())
        .add(Key::dict("artificialViscosity", "artificial viscosity { type ...; } (default none)")
                 .selects("artificialViscosity")
                 .optional())
        .add(Key::dict("impenetrability", "a close-pair energy that keeps stress-free material "
                                          "from pairing { distance 0.5; } (default none; "
                                          "docs/theory/impenetrability.md)")
                 .optional());
}

void loadCaseLibraries(const ControlSettings& control, const std::filesystem::path& caseDir)
{
    for (const auto& [name, where] : control.libraries)
    {
        LibraryLoader::load(name, where, caseDir);
    }
}

SchemeSettings SchemeSettings::read(const Dictionary& sphSchemes)
{
    const Params p = schema().validate(sphSchemes, "sphSchemes", 0, TypeEntry::isKey);
    SchemeSettings settings;
    settings.dimension = static_cast<int>(p.integer("dimension"));
    settings.kernel = &p.dict("kernel");
    settings.formulation = &p.dict("formulation");
    settings.stabilisation = &p.dict("stabilisation");
    settings.contact = p.has("contact") ? &p.dict("contact") : nullptr;
    settings.timeIntegration = p.has("timeIntegration") ? &p.dict("timeIntegration") : nullptr;
    settings.artificialViscosity =
        p.has("artificialViscosity") ? &p.dict("artificialViscosity") : nullptr;
    settings.impenetrability = p.has("impenetrability") ? &p.dict("impenetrability") : nullptr;
    return settings;
}

int readDimension(const Dictionary& sphSchemes)
{
    const Entry* entry = sphSchemes.find("dimension");
    Dictionary only("", sphSchemes.location());
    if (entry)
    {
        only.add(*entry);
    }
    const Params p = Schema()
                         .add(Key::integer("dimension", "space dimension of the case").range(1, 3))
                         .validate(only, "sphSchemes");
    return static_cast<int>(p.integer("dimension"));
}

} // namespace sph
