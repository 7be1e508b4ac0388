#pragma once
// The common part of the function objects: the `writeInterval` key, the output table and the
// decision whether a row is due (core/WriteSchedule.hpp, the rule of every output).

#include "core/WriteSchedule.hpp"
#include "functionObjects/DatFile.hpp"
#include "functionObjects/FunctionObject.hpp"

#include <memory>

namespace sph
{

template <int D>
class FunctionObjectModel : public FunctionObject<D>
{
public:
    static Schema commonSchema()
    {
        return Schema().add(Key::real("writeInterval", "time between rows [s]; 0 writes every "
                                                       "step")
                                .nonNegative()
                                .defaultValue("0"));
    }

    void start(double startTime, bool restarted) override
    {
        if (!restarted)
        {
            schedule_.restart();
        }
        if (writer())
        {
            file_->open(startTime, restarted);
        }
    }
    double nextWriteTime(double time, double deltaT) const override
    {
        return schedule_.nextAfter(time, deltaT);
    }
    void saveState(std::map<std::string, double>& state) const override
    {
        state["nextRow"] = schedule_.next();
    }
    void restoreState(const std::map<std::string, double>& state) override
    {
        const auto found = state.find("nextRow");
        if (found != state.end())
        {
            schedule_.next() = found->second;
        }
    }

protected:
    FunctionObjectModel(const Params& params, const typename FunctionObject<D>::Args& args)
        : FunctionObject<D>(args.name),
          schedule_(params.real("writeInterval"), params.location("writeInterval")),
          folder_(args.caseDir / "postProcessing" / args.name), ranks_(args.ranks)
    {
    }

    // Call once the columns are known.
    void setColumns(std::vector<std::string> columns)
    {
        file_ = std::make_unique<DatFile>(folder_ / (this->name() + ".dat"), std::move(columns));
    }
    // Whether a row is due at this time level: the first level at or after each multiple of
    // the interval (deltaT: the step size, for a round-off tolerance).
    bool rowDue(double time, double deltaT) const { return schedule_.due(time, deltaT); }
    // Every rank calls it with the same row (the objects reduce over the ranks first); the
    // writer writes it.
    void writeRow(double time, double deltaT, const std::vector<double>& values)
    {
        if (writer())
        {
            file_->write(time, values);
        }
        if (!stepChecked_ && deltaT > 0.0)
        {
            schedule_.checkStep(deltaT);
            stepChecked_ = true;
        }
        schedule_.written(time, deltaT);
    }
    double interval() const { return schedule_.interval(); }
    const std::filesystem::path& folder() const { return folder_; }
    bool writer() const { return !ranks_ || ranks_->writer; }

private:
    WriteSchedule schedule_;
    bool stepChecked_ = false; // the interval against the first step (checkStep)
    std::filesystem::path folder_;
    std::unique_ptr<DatFile> file_;
    const ParticleRanks* ranks_ = nullptr; // a distributed run's (null: serial)
};

} // namespace sph
