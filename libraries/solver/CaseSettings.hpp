#pragma once
// The run-control and scheme settings of a case, validated against their schemas:
//
// system/controlDict
//   endTime                | end of the simulation [s]                                | required
//   courant                | α in Δt = α h / c (seed eq. 17)                          | required
//   writeInterval          | time between VTK outputs [s] (timeStep: steps)           | required
//   writeControl           | adjustableRunTime: shorten the steps before each output  | adjustable-
//                          | and function-object row time to land on it exactly;      | RunTime
//                          | runTime: write at the first level at or after it;        |
//                          | timeStep: every writeInterval steps (OpenFOAM's words)   |
//   purgeWrite             | keep only the last N VTK outputs (0: keep all)           | 0
//   startFrom              | startTime, or latestTime to restart from the last output | startTime
//   startTime              | with startFrom startTime: 0 starts afresh, a later time  | 0
//                          | continues from the restartable output written then       |
//   stopAt                 | endTime, or writeNow: write the level and stop (read     | endTime
//                          | again while running: solver/StopRequest.hpp)             |
//   timeStepUpdateInterval | steps between recomputing c from the current F (0: keep | 1
//                          | the initial Δt, as for comparisons with other codes)     |
//   maxSteps               | stop after this many steps (benchmarks)                  | optional
//   libs                   | extra model libraries to load ("libX.so" ...)            | ()
//   functions              | function objects { name { type ...; } ... }              | optional
//
// system/sphSchemes
//   dimension     | 1, 2 or 3                                  | required
//   kernel        | { type cubicSpline; hOverDx 1.5; }         | required
//   formulation   | { type totalLagrangian; }                  | required
//   stabilisation | { type gradF; }                            | required
//   contact         | { type none; }                           | { type none; }
//   timeIntegration | { type leapfrog; }                       | { type leapfrog; }
//   artificialViscosity | { type monaghan; alpha 1; beta 2; }  | { type none; }

#include "core/CaseDictionaries.hpp"
#include "core/Schema.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sph
{

enum class WriteControl
{
    adjustableRunTime,
    runTime,
    timeStep
};

struct ControlSettings
{
    double endTime = 0.0;
    double courant = 0.0;
    double writeInterval = 0.0; // [s], or steps with WriteControl::timeStep
    WriteControl writeControl = WriteControl::adjustableRunTime;
    long purgeWrite = 0; // keep the last N outputs (0: all)
    bool startFromLatest = false;
    // startFrom startTime with startTime > 0: continue from the output written at that time.
    std::optional<double> startTime;
    SourceLocation startTimeLocation;
    bool stopAtWriteNow = false; // stopAt writeNow: write the first level and stop
    long timeStepUpdateInterval = 1;
    std::optional<long> maxSteps;
    double maxLoadImbalance = 1.2; // distributed runs: repartition above this (max / mean)
    const Dictionary* functions = nullptr;
    // The case's own model libraries (`libs`), with where each is named.
    std::vector<std::pair<std::string, SourceLocation>> libraries;

    static Schema schema();
    // Validates controlDict (nothing is loaded: see loadCaseLibraries).
    static ControlSettings read(const CaseDictionaries& dicts);
};

// The start-up step that loads the case's `libs`, after the default libraries and before any
// model is selected (a case's models may be in them). A library runs its registration code as
// it loads: a case is code.
void loadCaseLibraries(const ControlSettings& control, const std::filesystem::path& caseDir);

struct SchemeSettings
{
    int dimension = 0;
    const Dictionary* kernel = nullptr;
    const Dictionary* formulation = nullptr;
    const Dictionary* stabilisation = nullptr;
    const Dictionary* contact = nullptr; // null: none
    const Dictionary* timeIntegration = nullptr; // null: leapfrog
    const Dictionary* artificialViscosity = nullptr; // null: none
    const Dictionary* impenetrability = nullptr; // null: no close-pair energy

    static Schema schema();
    static SchemeSettings read(const Dictionary& sphSchemes);
};

// Only the `dimension` entry of system/sphSchemes (sphParticles reads nothing else there).
int readDimension(const Dictionary& sphSchemes);

} // namespace sph
