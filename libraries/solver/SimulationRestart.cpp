// Restart: `startFrom latestTime;` reads the newest restartable output of the series back into
// the registries (SimulationOutput.cpp writes it) and continues bit-identically.
#include "solver/Simulation.hpp"

#include "core/Format.hpp"
#include "core/InputError.hpp"
#include "io/PvtuFile.hpp"
#include "io/VtuFile.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

namespace sph
{

namespace
{

// The entry of the series written at `chosen` (the nearest within a relative 1e-6, so that a
// time copied from the log or the error below matches), if any.
const PvdSeries::Entry* entryAt(const PvdSeries& series, double chosen)
{
    const PvdSeries::Entry* nearest = nullptr;
    for (const auto& entry : series.entries())
    {
        if (std::abs(entry.time - chosen) <= 1e-6 * chosen &&
            (!nearest || std::abs(entry.time - chosen) < std::abs(nearest->time - chosen)))
        {
            nearest = &entry;
        }
    }
    return nearest;
}

// "0, 0.0002, 0.0004" (at most 20: the first and last ten around a gap).
std::string writtenTimes(const PvdSeries& series, const std::filesystem::path& folder)
{
    std::vector<double> times;
    for (const auto& entry : series.entries())
    {
        if (std::filesystem::exists(folder / entry.file))
        {
            times.push_back(entry.time);
        }
    }
    std::string text;
    for (std::size_t i = 0; i < times.size(); ++i)
    {
        if (times.size() > 20 && i == 10)
        {
            text += ", ... (" + std::to_string(times.size() - 20) + " more)";
            i = times.size() - 10;
        }
        text += (text.empty() ? "" : ", ") + formatNumber(times[i], 9);
    }
    return text;
}

} // namespace

template <int D>
bool Simulation<D>::restoreLatest(RunLog& log)
{
    pvd_.load();
    const std::filesystem::path folder = dicts_.caseDir() / "VTK";
    // startFrom startTime with startTime > 0: that output, or an error naming the written ones.
    const PvdSeries::Entry* chosen =
        control_.startTime ? entryAt(pvd_, *control_.startTime) : nullptr;
    if (control_.startTime && (!chosen || !std::filesystem::exists(folder / chosen->file)))
    {
        const std::string times = writtenTimes(pvd_, folder);
        throw InputError(control_.startTimeLocation,
                         "no output was written at startTime " +
                             formatNumber(*control_.startTime, 9) + " (the series VTK/" +
                             pvd_.file().filename().string() + ")",
                         {times.empty() ? "VTK/ holds no output: run from startTime 0 first."
                                        : "Written times: " + times + ".",
                          "startTime 0 starts afresh; 'startFrom latestTime;' continues from "
                          "the last output."});
    }
    for (auto entry = pvd_.entries().rbegin(); entry != pvd_.entries().rend(); ++entry)
    {
        const std::filesystem::path path = folder / entry->file;
        if (chosen && &*entry != chosen)
        {
            continue;
        }
        if (!std::filesystem::exists(path))
        {
            continue;
        }
        // A distributed run's output (.pvtu) is read whole, in the order of the particle file,
        // so it restarts on any number of ranks, or serially; a serial output restarts a
        // distributed run with each particle's index as its global index.
        VtuData data = path.extension() == ".pvtu" ? readPvtu(path, "globalId") : readVtu(path);
        if (comm_.parallel() && data.pointData.count("globalId") == 0)
        {
            VtuArray ids{1, std::vector<double>(data.pointCount()), true, {}, {}};
            std::iota(ids.values.begin(), ids.values.end(), 0.0);
            data.pointData["globalId"] = ids;
        }
        const auto& fields = data.fieldData;
        const auto number = [&](const std::string& name) -> std::optional<double> {
            const auto found = fields.find(restartPrefix + name);
            return found == fields.end() || found->second.values.size() != 1
                       ? std::nullopt
                       : std::optional<double>(found->second.values[0]);
        };
        if (number("restartable") != 1.0)
        {
            if (chosen)
            {
                throw InputError(control_.startTimeLocation,
                                 "the output at startTime " + formatNumber(entry->time, 9) +
                                     " ('" + path.string() + "') is not restartable: it is the "
                                     "last good level written before a numerical failure",
                                 {"Choose an earlier written time."});
            }
            continue;
        }
        const std::string file = path.string();
        if (data.pointCount() != particles_.size() || number("dimension") != D ||
            !number("step") || fields.count("TimeValue") == 0 ||
            data.stringFields.count("bodyNames") == 0 ||
            data.stringFields.at("bodyNames") != bodyNames_)
        {
            throw InputError("cannot restart from '" + file + "': it holds " +
                                 std::to_string(data.pointCount()) +
                                 " particles of other bodies or dimension than the case now",
                             {"The case changed since that output; start afresh with startFrom "
                              "startTime (or run Allclean)."});
        }
        readState<D>(data, fields_, runScalars_, file);
        // A distributed run rebuilds the reference of each rank's share when it has one.
        const ForceStatus status = comm_.parallel() ? ForceStatus{} : reference_->restored(particles_);
        if (!status.ok())
        {
            throw InputError("cannot restart from '" + file + "': the saved reference "
                             "configuration is singular at " +
                                 particleName(static_cast<std::size_t>(status.badParticle)));
        }
        step_ = static_cast<long>(*number("step"));
        time_ = fields.at("TimeValue").values.at(0);
        for (auto& object : functionObjects_)
        {
            const std::string prefix = restartPrefix + object->statePrefix();
            std::map<std::string, double> own;
            for (const auto& [key, value] : fields)
            {
                if (key.rfind(prefix, 0) == 0)
                {
                    own[key.substr(prefix.size())] = value.values.at(0);
                }
            }
            if (!own.empty())
            {
                object->restoreState(own);
            }
        }
        // This level is written again, replacing its file atomically; it stays in the series
        // meanwhile, so that a restart that fails to write it (a full disk) loses nothing.
        // Later outputs are stale (rank 0 clears them; every rank keeps the same series). Not
        // before every rank has read the series and its output: a rank that read the shortened
        // series would restart from an older level.
        comm_.barrier();
        const std::size_t listed = pvd_.entries().size();
        pvd_.keepThrough(time_);
        const std::size_t later = listed - pvd_.entries().size();
        if (comm_.rank() == 0)
        {
            pvd_.write();
            std::vector<std::filesystem::path> stale;
            for (const auto& other : std::filesystem::directory_iterator(folder))
            {
                if (outputIndexOf(other.path().filename().string(), caseName_) > outputIndex_)
                {
                    stale.push_back(other.path());
                }
            }
            for (const auto& file : stale)
            {
                std::filesystem::remove_all(file);
            }
        }
        log.line("Restart     from " + path.filename().string() + " at step " +
                 std::to_string(step_) + ", t = " + std::to_string(time_) + " s" +
                 (later > 0 ? " (the " + std::to_string(later) +
                                  " later outputs are removed: they are computed again)"
                            : ""));
        return true;
    }
    log.line("Restart     no restartable output in VTK/; starting from the initial state");
    return false;
}

template class Simulation<1>;
template class Simulation<2>;
template class Simulation<3>;

} // namespace sph
