#pragma once
// Runs the variants of a study, each in its own copy of the case under
// postProcessing/study/runs/<variant>/, and records what each cost and how accurate it was.
// A variant whose record (study.json) exists is not run again: an interrupted study resumes.

#include "StudyDefinition.hpp"

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace sph
{

struct VariantResult
{
    StudyVariant variant;
    std::string status = "not run"; // finished | failed
    std::string failure;
    double particles = 0.0;
    double steps = 0.0;
    double wallSeconds = 0.0;       // median over repeats, time loop only
    double usPerParticleStep = 0.0; // median, output excluded
    double peakMemoryMB = 0.0;
    std::map<std::string, double> metrics; // NaN where not available
    bool reused = false;                   // from an earlier, interrupted run of the study
};

class StudyRunner
{
public:
    StudyRunner(std::filesystem::path caseDir, const StudyDefinition& study,
                std::filesystem::path binDir);

    // Runs (or reuses) every variant, printing progress; returns the results in order.
    std::vector<VariantResult> run();

    const std::filesystem::path& studyDir() const { return studyDir_; }

private:
    VariantResult runVariant(const StudyVariant& variant);
    void computeMetrics(VariantResult& result) const;
    std::filesystem::path variantDir(const std::string& name) const;

    std::filesystem::path caseDir_;
    const StudyDefinition& study_;
    std::filesystem::path binDir_;
    std::filesystem::path studyDir_;
    std::set<std::string> finished_; // the variants run so far that finished
};

} // namespace sph
