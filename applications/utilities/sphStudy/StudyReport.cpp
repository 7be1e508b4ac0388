#include "StudyReport.hpp"
#include "StudyMetric.hpp"

#include "core/Format.hpp"
#include "core/Process.hpp"
#include "io/AtomicFile.hpp"
#include "io/Csv.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>

namespace sph
{

namespace
{

// A table cell: 4 significant digits, "—" for a value that was not measured.
std::string number(double value)
{
    return std::isnan(value) ? "—" : formatNumber(value, 4);
}

// The same with a fixed number of decimals.
std::string number(double value, int decimals)
{
    return std::isnan(value) ? "—" : formatFixed(value, decimals);
}

// A CSV cell: 10 significant digits, empty when not measured.
std::string csvNumber(double value)
{
    return std::isnan(value) ? "" : formatNumber(value, 10);
}

// "pass" (every bound of `stable` holds), "failed" (the run stopped), or
// "fail: <the first bound that does not hold>".
std::string verdictOf(const StudyDefinition& study, const VariantResult& result)
{
    if (result.status != "finished")
    {
        return "failed";
    }
    for (const auto& bound : study.stable)
    {
        const double value = result.metrics.at(bound.metric);
        if (std::isnan(value))
        {
            return "fail: " + bound.metric + " not measured";
        }
        if (value < bound.min)
        {
            return "fail: " + bound.metric + " " + number(value) + " < " + number(bound.min);
        }
        if (value > bound.max)
        {
            return "fail: " + bound.metric + " " + number(value) + " > " + number(bound.max);
        }
    }
    return "pass";
}

// Per level of the groupBy axis: how many of its runs are stable, and which are not.
void writeVerdictSummary(std::ostringstream& md, const StudyDefinition& study,
                         const std::vector<VariantResult>& results, std::size_t group)
{
    md << "\n**Verdict of each " << study.groupBy << "** (pass = the run finished, and";
    for (std::size_t i = 0; i < study.stable.size(); ++i)
    {
        const auto& bound = study.stable[i];
        md << (i == 0 ? " " : ", ") << bound.metric;
        if (std::isfinite(bound.min))
        {
            md << " ≥ " << number(bound.min);
        }
        if (std::isfinite(bound.min) && std::isfinite(bound.max))
        {
            md << " and";
        }
        if (std::isfinite(bound.max))
        {
            md << " ≤ " << number(bound.max);
        }
    }
    md << "):\n\n";
    for (const auto& level : study.axes[group].levels)
    {
        std::size_t runs = 0;
        std::size_t stable = 0;
        std::string others;
        for (const auto& r : results)
        {
            if (r.variant.levels[group] != level.name)
            {
                continue;
            }
            ++runs;
            const std::string verdict = verdictOf(study, r);
            if (verdict == "pass")
            {
                ++stable;
            }
            else
            {
                others += (others.empty() ? "; not: " : ", ") + r.variant.name + " (" + verdict +
                          ")";
            }
        }
        md << "- " << level.name << ": passes in " << stable << " of " << runs << " run"
           << (runs == 1 ? "" : "s") << others << "\n";
    }
}

void writePlots(const std::filesystem::path& studyDir, const StudyDefinition& study,
                const std::vector<VariantResult>& results, std::size_t group);

} // namespace

void writeStudyReport(const std::filesystem::path& studyDir, const StudyDefinition& study,
                      const std::vector<VariantResult>& results)
{
    const std::string primary = study.metrics.front()->name();

    // results.csv
    std::ostringstream csv;
    csv << "variant";
    for (const auto& axis : study.axes)
    {
        csv << "," << csvField(axis.name);
    }
    csv << ",status,particles,steps,wallSeconds,usPerParticleStep,peakMemoryMB";
    for (const auto& metric : study.metrics)
    {
        csv << "," << csvField(metric->name());
    }
    csv << (study.stable.empty() ? "" : ",verdict") << ",failure\n";
    for (const auto& r : results)
    {
        csv << csvField(r.variant.name);
        for (const auto& level : r.variant.levels)
        {
            csv << "," << csvField(level);
        }
        csv << "," << csvField(r.status) << "," << csvNumber(r.particles) << "," << csvNumber(r.steps) << ","
            << csvNumber(r.wallSeconds) << "," << csvNumber(r.usPerParticleStep) << ","
            << csvNumber(r.peakMemoryMB);
        for (const auto& metric : study.metrics)
        {
            csv << "," << csvNumber(r.metrics.at(metric->name()));
        }
        if (!study.stable.empty())
        {
            csv << "," << csvField(verdictOf(study, r));
        }
        csv << "," << csvField(r.failure) << "\n";
    }
    writeTextAtomically(studyDir / "results.csv", csv.str());

    // results.md
    std::ostringstream md;
    md << "| variant |";
    for (const auto& axis : study.axes)
    {
        md << " " << axis.name << " |";
    }
    md << " status | particles | wall [s] | µs per particle-step | memory [MB] |";
    for (const auto& metric : study.metrics)
    {
        md << " " << metric->name() << " |";
    }
    const bool verdicts = !study.stable.empty();
    md << (verdicts ? " verdict |" : "") << "\n| --- |";
    for (std::size_t i = 0; i < study.axes.size() + 5 + study.metrics.size() + verdicts; ++i)
    {
        md << " --- |";
    }
    md << "\n";
    for (const auto& r : results)
    {
        md << "| " << r.variant.name << " |";
        for (const auto& level : r.variant.levels)
        {
            md << " " << level << " |";
        }
        md << " " << r.status << " | " << number(r.particles, 0) << " | "
           << number(r.wallSeconds) << " | " << number(r.usPerParticleStep, 3) << " | "
           << number(r.peakMemoryMB, 1) << " |";
        for (const auto& metric : study.metrics)
        {
            md << " " << number(r.metrics.at(metric->name())) << " |";
        }
        md << (verdicts ? " " + verdictOf(study, r) + " |" : std::string()) << "\n";
    }
    const std::size_t group = study.axisIndex(study.groupBy);
    if (verdicts)
    {
        writeVerdictSummary(md, study, results, group);
    }
    if (!study.rank)
    {
        writeTextAtomically(studyDir / "results.md", md.str());
        writePlots(studyDir, study, results, group);
        return;
    }
    // The Pareto front: no other finished variant is both faster and more accurate.
    std::vector<const VariantResult*> finished;
    for (const auto& r : results)
    {
        if (r.status == "finished" && !std::isnan(r.metrics.at(primary)) &&
            !std::isnan(r.wallSeconds))
        {
            finished.push_back(&r);
        }
    }
    std::sort(finished.begin(), finished.end(),
              [](const VariantResult* a, const VariantResult* b)
              { return a->wallSeconds < b->wallSeconds; });
    md << "\n**Best " << primary << " for the wall time** (the Pareto front: no other finished "
       << "variant is both faster and more accurate), fastest first:\n\n";
    double best = std::numeric_limits<double>::infinity();
    for (const auto* r : finished)
    {
        const double error = r->metrics.at(primary);
        if (error < best)
        {
            best = error;
            md << "- " << r->variant.name << ": " << primary << " " << number(error) << " in "
               << number(r->wallSeconds) << " s\n";
        }
    }
    md << "\n**Best " << primary << " of each " << study.groupBy << "** (and its cost):\n\n";
    for (const auto& level : study.axes[group].levels)
    {
        const VariantResult* bestOfGroup = nullptr;
        for (const auto* r : finished)
        {
            if (r->variant.levels[group] == level.name &&
                (!bestOfGroup || r->metrics.at(primary) < bestOfGroup->metrics.at(primary)))
            {
                bestOfGroup = r;
            }
        }
        std::size_t failed = 0;
        for (const auto& r : results)
        {
            failed += r.variant.levels[group] == level.name && r.status == "failed";
        }
        md << "- " << level.name << ": ";
        if (bestOfGroup)
        {
            md << number(bestOfGroup->metrics.at(primary)) << " (" << bestOfGroup->variant.name
               << ", " << number(bestOfGroup->wallSeconds) << " s)";
        }
        else
        {
            md << "no finished run";
        }
        if (failed > 0)
        {
            md << "; " << failed << " run" << (failed > 1 ? "s" : "") << " failed";
        }
        md << "\n";
    }
    writeTextAtomically(studyDir / "results.md", md.str());
    writePlots(studyDir, study, results, group);
}

namespace
{

void writePlots(const std::filesystem::path& studyDir, const StudyDefinition& study,
                const std::vector<VariantResult>& results, std::size_t group)
{
    const std::string primary = study.metrics.front()->name();
    // Plot data: one line per level of groupBy and of the axes other than `along`, through the
    // levels of `along`.
    const std::size_t along = study.axisIndex(study.along);
    std::map<std::string, std::vector<const VariantResult*>> lines;
    for (const auto& r : results)
    {
        std::string name = r.variant.levels[group];
        for (std::size_t a = 0; a < study.axes.size(); ++a)
        {
            if (a != group && a != along)
            {
                name += "_" + r.variant.levels[a];
            }
        }
        lines[name].push_back(&r);
    }
    const std::filesystem::path plotDir = studyDir / "plot";
    std::filesystem::create_directories(plotDir);
    std::ostringstream gp;
    gp << "# gnuplot script written by sphStudy: " << primary << " against cost\n"
       << "set terminal pngcairo size 1100,750 font 'Sans,10' noenhanced\n"
       << "set logscale xy\nset grid\nset key outside right\nset datafile missing 'NaN'\n"
       << "set ylabel '" << primary << "'\n";
    std::string plots;
    for (const auto& [name, members] : lines)
    {
        std::ostringstream data;
        data << "# " << study.along << " wallSeconds " << primary << " particles\n";
        for (const auto& level : study.axes[along].levels)
        {
            for (const auto* r : members)
            {
                if (r->variant.levels[along] == level.name)
                {
                    const double error = r->status == "finished" ? r->metrics.at(primary) : NAN;
                    data << level.name << " " << csvNumber(r->wallSeconds) << " "
                         << (std::isnan(error) ? std::string("NaN") : csvNumber(error)) << " "
                         << csvNumber(r->particles) << "\n";
                }
            }
        }
        writeTextAtomically(plotDir / (name + ".dat"), data.str());
        plots += (plots.empty() ? "" : ", ") + std::string("'plot/") + name +
                 ".dat' using %X:3 with linespoints lw 2 title '" + name + "'";
    }
    const auto plotOf = [&](const std::string& x)
    {
        std::string command = plots;
        for (std::string::size_type pos; (pos = command.find("%X")) != std::string::npos;)
        {
            command.replace(pos, 2, x);
        }
        return command;
    };
    gp << "set output 'errorVsTime.png'\nset xlabel 'wall time [s]'\nset title '" << primary
       << " against wall time (failed runs are left out)'\nplot " << plotOf("2") << "\n"
       << "set output 'errorVsParticles.png'\nset xlabel 'particles'\nset title '" << primary
       << " against the number of particles'\nplot " << plotOf("4") << "\n";
    writeTextAtomically(studyDir / "study.gp", gp.str());
    if (const auto gnuplot = findInPath("gnuplot"))
    {
        if (runProgram(*gnuplot, {"study.gp"}, studyDir / "log.gnuplot", studyDir, "") != 0)
        {
            std::fprintf(stderr, "sphStudy: gnuplot failed on %s/study.gp (see log.gnuplot)\n",
                         studyDir.c_str());
        }
    }
}

} // namespace

} // namespace sph
