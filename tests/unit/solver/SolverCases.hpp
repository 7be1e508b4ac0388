#pragma once
// Small cases written by the solver tests.

#include "io/PvdSeries.hpp"
#include "io/VtuFile.hpp"
#include "support/CaseRunner.hpp"

#include <fstream>
#include <limits>

namespace sph::test
{

// A 2D block of 10x10 particles (spacing 1 mm) of Neo-Hookean rubber, bottom row fixed, top
// half moving sideways: shear oscillation. `schemes` is the sphSchemes body after `dimension`.
inline std::filesystem::path writeBlockCase(const std::filesystem::path& folder,
                                            const std::string& schemes, double endTime,
                                            double writeInterval)
{
    std::filesystem::create_directories(folder / "system");
    std::filesystem::create_directories(folder / "constant");
    std::ofstream(folder / "system" / "controlDict")
        << "endTime " << endTime << ";\ncourant 0.3;\nwriteInterval " << writeInterval << ";\n"
        << "functions\n{\n    energy { type energy; }\n"
        << "    corner { type probes; points ((0.0095 0.0095)); fields (displacement velocity J); }\n}\n";
    std::ofstream(folder / "system" / "sphSchemes") << "dimension 2;\n" << schemes << "\n";
    std::ofstream(folder / "system" / "particlesDict")
        << "block { type box; min (0 0); max (0.01 0.01); spacing 1e-3; }\n";
    std::ofstream(folder / "constant" / "bodies")
        << "block\n{\n    material { type neoHookean; mu 1e5; kappa 1e6; rho 1000; }\n"
        << "    initialVelocity { top { region { type box; min (0 0.005); max (0.01 0.01); } "
           "velocity (2 0.5); } }\n"
        << "    constraints { base { type fixed; region { type box; min (0 0); max (0.01 "
           "0.001); } } }\n}\n";
    return folder;
}

// ∫ f dt / (t_end - t_0) over the rows of a table from time `from` on (trapezoid rule; the
// steps vary a little).
inline double timeAverage(const Table& table, const std::string& column,
                          double from = -std::numeric_limits<double>::infinity())
{
    const auto t = table.column("time");
    const auto f = table.column(column);
    double integral = 0.0;
    double duration = 0.0;
    for (std::size_t i = 1; i < t.size(); ++i)
    {
        if (t[i - 1] >= from)
        {
            integral += 0.5 * (f[i] + f[i - 1]) * (t[i] - t[i - 1]);
            duration += t[i] - t[i - 1];
        }
    }
    return integral / duration;
}

// A small block of stiff linear-elastic material (c0 = 116 m/s, spacing 1 cm) against rigid
// walls, with the `energy` and `wallForce` (named `walls`) tables written every step.
// `particles` and `bodies` are the bodies of system/particlesDict and constant/bodies;
// `walls` is constant/walls.
inline std::filesystem::path writeWallCase(const std::filesystem::path& folder, int dimension,
                                           const std::string& particles,
                                           const std::string& bodies, const std::string& walls,
                                           double endTime, double courant = 0.3)
{
    std::filesystem::create_directories(folder / "system");
    std::filesystem::create_directories(folder / "constant");
    std::ofstream(folder / "system" / "controlDict")
        << "endTime " << endTime << ";\ncourant " << courant << ";\nwriteInterval " << endTime
        << ";\nfunctions\n{\n    energy { type energy; }\n    walls { type wallForce; }\n}\n";
    std::ofstream(folder / "system" / "sphSchemes")
        << "dimension " << dimension << ";\nkernel { type cubicSpline; hOverDx 1.5; }\n"
        << "formulation { type totalLagrangian; }\nstabilisation { type none; }\n";
    std::ofstream(folder / "system" / "particlesDict") << particles << "\n";
    std::ofstream(folder / "constant" / "bodies")
        << "stiff { type linearElastic; E 1e7; nu 0.3; rho 1000; }\n" << bodies << "\n";
    std::ofstream(folder / "constant" / "walls") << walls << "\n";
    return folder;
}

// The colliding rings coarsened to 2 mm (1120 particles, above the size at which loops use
// threads), run by sphSolid with `arguments`; their last output.
inline VtuData runCoarseRings(const std::filesystem::path& folder,
                              const std::vector<std::string>& arguments)
{
    const auto caseDir = copyTutorial("rings2D/collidingRings", folder);
    REQUIRE(runParticles(caseDir, {"-set", "ringA.spacing=2e-3", "-set", "ringB.spacing=2e-3"}) == 0);
    REQUIRE(runSolver(caseDir, arguments) == 0);
    PvdSeries series(caseDir / "VTK" / "collidingRings.pvd");
    series.load();
    return readVtu(caseDir / "VTK" / series.entries().back().file);
}

// The last output a run wrote (VTK/<case folder name>.pvd's last entry).
inline VtuData lastOutput(const std::filesystem::path& caseDir)
{
    PvdSeries series(caseDir / "VTK" / (caseDir.filename().string() + ".pvd"));
    series.load();
    REQUIRE(!series.entries().empty());
    return readVtu(caseDir / "VTK" / series.entries().back().file);
}

// Two outputs hold the same state bit for bit: the points, every point array (display and
// restart alike) and every number of the field data.
inline void requireIdenticalState(const VtuData& a, const VtuData& b)
{
    REQUIRE(a.points.size() == b.points.size());
    CHECK(a.points == b.points);
    REQUIRE(a.pointData.size() == b.pointData.size());
    for (const auto& [name, array] : a.pointData)
    {
        INFO(name);
        REQUIRE(b.pointData.count(name));
        CHECK(array.values == b.pointData.at(name).values);
    }
    REQUIRE(a.fieldData.size() == b.fieldData.size());
    for (const auto& [name, array] : a.fieldData)
    {
        INFO(name);
        REQUIRE(b.fieldData.count(name));
        CHECK(array.values == b.fieldData.at(name).values);
    }
}

} // namespace sph::test
