#pragma once
// Running the real applications on case folders from tests: in-process (sphSolidMain) or as a
// separate process (for exit codes and signals), plus readers for their outputs.

#include "support/TestSupport.hpp"

#include "io/DatTable.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sph::test
{

// The repository's source folder (tutorials live there).
std::filesystem::path sourceDir();

// Copies tutorials/<relative> into `into`/<name of the tutorial> and returns that folder.
std::filesystem::path copyTutorial(const std::string& relative, const std::filesystem::path& into);

// Runs sphParticles / sphSolid in this process on `caseDir` with extra arguments.
int runParticles(const std::filesystem::path& caseDir, const std::vector<std::string>& args = {});
int runSolver(const std::filesystem::path& caseDir, const std::vector<std::string>& args = {});

// Runs build/bin/<app> as a child process; returns its exit code, output in *output.
int runProcess(const std::string& app, const std::vector<std::string>& args,
               std::string* output = nullptr);

// A table written by a function object: column("time"), column("drift"), ... (io/DatTable).
using Table = DatTable;
Table readTable(const std::filesystem::path& file);

// A number from the run's postProcessing/summary.json, by path: "functions/energy/maxDrift".
double summaryValue(const std::filesystem::path& caseDir, const std::string& path);

// A file's bytes as a string (outputs compared byte for byte).
std::string fileText(const std::filesystem::path& file);

// Replaces or adds `key value;` at the top level of a dictionary file (simple text edit).
void setEntry(const std::filesystem::path& file, const std::string& key, const std::string& value);

} // namespace sph::test
