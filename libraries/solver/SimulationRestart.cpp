// Restart: `startFrom latestTime;` reads the newest restartable output of the series back into
// the registries (SimulationOutput.cpp writes it) and continues bit-identically.
#include "solver/Simulation.hpp"

#include "core/InputError.hpp"
#include "io/PvtuFile.hpp"
#include "io/VtuFile.hpp"

#include <numeric>
#include <optional>

namespace sph
{

template <int D>
bool Simulation<D>::restoreLatest(RunLog& log)
{
    pvd_.load();
    const std::filesystem::path folder = dicts_.caseDir() / "VTK";
    for (auto entry = pvd_.entries().rbegin(); entry != pvd_.entries().rend(); ++entry)
    {
        const std::filesystem::path path = folder / entry->file;
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
        // This level is computed and written again; later outputs are stale (rank 0 clears them;
        // every rank keeps the same series). Not before every rank has read the series and its
        // output: a rank that read the shortened series would restart from an older level.
        comm_.barrier();
        pvd_.keepBefore(time_);
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
                 std::to_string(step_) + ", t = " + std::to_string(time_) + " s");
        return true;
    }
    log.line("Restart     no restartable output in VTK/; starting from the initial state");
    return false;
}

template class Simulation<1>;
template class Simulation<2>;
template class Simulation<3>;

} // namespace sph
