#pragma once
// The study's results as files: results.csv, results.md (a table, the variants that give the
// best error for their cost — the Pareto front — and the best of each group), and gnuplot
// plots of the first metric against wall time and against the number of particles.

#include "StudyRunner.hpp"

namespace sph
{

void writeStudyReport(const std::filesystem::path& studyDir, const StudyDefinition& study,
                      const std::vector<VariantResult>& results);

} // namespace sph
