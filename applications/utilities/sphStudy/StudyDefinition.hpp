#pragma once
// system/studyDict: what a study varies, how it measures error, how it plots.
//
//   axes                                     // every combination of levels is a variant
//   {
//       resolution { n40 { particles ("bar.n=40"); } n80 { particles ("bar.n=80"); } }
//       scheme     { TLnone  { solver ("formulation.type=totalLagrangian"
//       "stabilisation.type=none"); }
//                    ULgradF { solver ("formulation.type=updatedLagrangian"
//                    "stabilisation.type=gradF"); } }
//   }
//   common { solver ("writeInterval=1"); }  // overrides every variant shares (optional)
//   repeats  1;                 // runs per variant; times are their median
//   threads  2;                 // OpenMP threads per run (0: all)
//   metrics                     // the first is the one plotted
//   {
//       tipError { type exactSolution; functionObject tipError; value relativeLinfError; }
//       energy   { type summary; value functions/energy/maxDrift; }
//       extent   { type referenceVariant; variant n640_ULgradF; file
//       postProcessing/extent/extent.dat;
//                  column ringA_maxDisplacement; norm max; }
//       growth   { type referenceVariant; referenceLevels { seed clean; }   // each variant against
//                  file postProcessing/probe/probe.dat; column p0_displacement_x; scale 1e-9; }
//                  // the one that differs only in these levels (here: the same scheme, no noise)
//       data     { type referenceFile; file postProcessing/x/x.dat; column c; reference "ref.dat";
//                  referenceColumn 2; norm rms; }
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
// as one -set argument. Variant names join the level names with '_' in axis order.

#include "core/Dictionary.hpp"

#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace sph
{

struct StudyLevel
{
    std::string name;
    std::vector<std::string> particles; // -set overrides for sphParticles
    std::vector<std::string> solver;    // -set overrides for sphSolid
};

struct StudyAxis
{
    std::string name;
    std::vector<StudyLevel> levels;
};

struct StudyMetric
{
    std::string name;
    std::string type;  // exactSolution | summary | referenceVariant | referenceFile
    std::string value; // summary path (exactSolution: functions/<fo>/<value>)
    std::string file;  // table in each variant (referenceVariant/referenceFile)
    std::string column;
    std::string variant; // the reference variant, or
    std::map<std::string, std::string>
        referenceLevels;   // axis -> level: the variant that differs only there
    std::string reference; // referenceFile: the reference table (relative to the case)
    std::string referenceColumn;
    std::string norm;   // max | rms (of the difference, relative to max |reference|)
    double scale = 0.0; // > 0: divide the difference by this instead
    SourceLocation where;
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
    std::vector<StudyAxis> axes;
    StudyLevel common; // overrides given to every variant first
    std::vector<StudyMetric> metrics;
    long repeats = 1;
    long threads = 0;
    std::string groupBy; // axis giving one line per level
    std::string along;   // axis along which the lines connect points
    std::vector<StabilityBound> stable; // empty: no verdict column
    bool rank = true;                   // report the Pareto front of the first metric

    // Reads and validates system/studyDict.
    static StudyDefinition read(const Dictionary& studyDict);
    // Every combination of levels, references first.
    std::vector<StudyVariant> variants() const;
    std::size_t axisIndex(const std::string& name) const;
    // The variant a referenceVariant metric compares `variant` with.
    std::string referenceOf(const StudyMetric& metric, const StudyVariant& variant) const;
};

} // namespace sph
