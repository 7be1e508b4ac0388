#pragma once
// system/studyDict: what a study varies, how it measures each run, how it plots.
//
//   baseCase "../dykaBar";      // optional: the case the variants copy (default: this one)
//   axes                        // every combination of levels is a variant
//   {
//       resolution
//       {
//           n40  { particles ("bar.n=40"); }
//           n160 { particles ("bar.n=160"); only { scheme (ULgradF); } }  // not with TLnone
//       }
//       scheme
//       {
//           TLnone  { solver ("formulation.type=totalLagrangian" "stabilisation.type=none"); }
//           ULgradF { solver ("formulation.type=updatedLagrangian" "stabilisation.type=gradF"); }
//       }
//   }
//   common { solver ("writeInterval=1"); }  // overrides every variant shares (optional)
//   repeats  1;                 // runs per variant; times are their median
//   threads  2;                 // OpenMP threads per run (0: all)
//   metrics                     // name { type T; keys of T }; the first is the one plotted
//   {
//       tipError { type exactSolution; functionObject tipError; value relativeLinfError; }
//       energy   { type summary; value functions/energy/maxDrift; }
//       radius   { type summary; value functions/shape/bar_final_max_x; plusSpacings 0.5;
//                  reference 7.165e-3; }   // the relative error of the body's extent
//       extent   { type referenceVariant; variant n640_ULgradF;
//                  file postProcessing/extent/extent.dat; column ringA_maxDisplacement; }
//       growth   { type referenceVariant; referenceLevels { seed clean; }   // each variant against
//                  file postProcessing/probe/probe.dat; column p0_displacement_x; scale 1e-9; }
//                  // the one that differs only in these levels (here: the same scheme, no noise)
//       data     { type referenceFile; file postProcessing/x/x.dat; column c; reference "ref.dat";
//                  referenceColumn "2"; norm rms; }
//   }
//   plot { groupBy scheme; along resolution; }
//   stable                      // optional: a verdict per run, pass when every bound holds
//   {
//       maxIndicator { max 0.1; }
//       minDistance  { min 0.5; }
//   }
//   rank     no;                // list the error-for-time Pareto front (default yes)
//
// A level's `particles` overrides go to sphParticles, its `solver` overrides to sphSolid, each
// as one -set argument; its optional `only { axis (level ...); }` combines it with those levels
// of other axes alone. Variant names join the level names with '_' in axis order. Each variant
// runs in a copy of the base case's system/ and constant/ under postProcessing/study/runs/ of
// the study's own folder, so one case can have several studies (e.g. tutorials/*/schemeComparison).
//
// The metric types are a model family (StudyMetric.hpp, one file each under metrics/): the keys
// of each, with their defaults, are listed by `sphStudy -listTypes studyMetric`:
//   exactSolution     functionObject; value (default relativeLinfError): a result of an
//                     exactSolution function object in each run's summary.json
//   summary           value: any number of summary.json by path (functions/energy/maxDrift);
//                     plusSpacings n: plus n run spacings; reference r: |value − r| / |r|
//   referenceVariant  file, column; variant or referenceLevels; norm max|rms|mean (default
//                     max; mean: |mean of the difference|, a plateau's offset);
//                     scale: a table column against another variant's, relative to
//                     max |reference| (or to scale)
//   referenceFile     file, column; reference, referenceColumn (a name, or a number in
//                     quotes); norm; scale: the same against a table of the case

#include "core/Dictionary.hpp"

#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace sph
{

class StudyMetric; // StudyMetric.hpp

struct StudyLevel
{
    std::string name;
    std::vector<std::string> particles; // -set overrides for sphParticles
    std::vector<std::string> solver;    // -set overrides for sphSolid
    // axis -> the levels of it this level is combined with (an axis not named: all of them)
    std::map<std::string, std::vector<std::string>> only;
};

struct StudyAxis
{
    std::string name;
    std::vector<StudyLevel> levels;
};

// A bound on one metric that a finished run must meet to be called stable.
struct StabilityBound
{
    std::string metric;
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
};

struct StudyVariant
{
    std::string name;
    std::vector<std::string> levels; // one per axis
    std::vector<std::string> particles;
    std::vector<std::string> solver;
};

struct StudyDefinition
{
    std::filesystem::path baseCase; // the case each variant copies (default: the study's own)
    std::vector<StudyAxis> axes;
    StudyLevel common; // overrides given to every variant first
    std::vector<std::shared_ptr<const StudyMetric>> metrics; // in studyDict's order
    long repeats = 1;
    long threads = 0;
    std::string groupBy; // axis giving one line per level
    std::string along;   // axis along which the lines connect points
    std::vector<StabilityBound> stable; // empty: no verdict column
    bool rank = true;                   // report the Pareto front of the first metric

    // Reads and validates system/studyDict of the case `caseDir`.
    static StudyDefinition read(const Dictionary& studyDict, const std::filesystem::path& caseDir);
    // Every combination of levels that their `only` allows, references first.
    std::vector<StudyVariant> variants() const;
    std::size_t axisIndex(const std::string& name) const;

private:
    // The odometer over the levels (index[a]: the level of axis a); false after the last.
    bool nextCombination(std::vector<std::size_t>& index) const;
    bool allowed(const std::vector<std::size_t>& index) const;
};

} // namespace sph
