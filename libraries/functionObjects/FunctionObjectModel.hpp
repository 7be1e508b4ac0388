#pragma once
// The common part of the function objects: the `writeInterval` key, the output table and the
// decision whether a row is due.

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
            nextRow_ = 0.0;
        }
        file_->open(startTime, restarted);
    }
    void saveState(std::map<std::string, double>& state) const override
    {
        state["nextRow"] = nextRow_;
    }
    void restoreState(const std::map<std::string, double>& state) override
    {
        const auto found = state.find("nextRow");
        if (found != state.end())
        {
            nextRow_ = found->second;
        }
    }

protected:
    FunctionObjectModel(const Params& params, const typename FunctionObject<D>::Args& args)
        : FunctionObject<D>(args.name), interval_(params.real("writeInterval")),
          folder_(args.caseDir / "postProcessing" / args.name)
    {
    }

    // Call once the columns are known.
    void setColumns(std::vector<std::string> columns)
    {
        file_ = std::make_unique<DatFile>(folder_ / (this->name() + ".dat"), std::move(columns));
    }
    // Whether a row is due at this time level: the first level at or after each multiple of
    // the interval (deltaT: the step size, for a round-off tolerance).
    bool rowDue(double time, double deltaT) const
    {
        return interval_ <= 0.0 || time >= nextRow_ - 1e-6 * deltaT;
    }
    void writeRow(double time, double deltaT, const std::vector<double>& values)
    {
        file_->write(time, values);
        if (interval_ > 0.0)
        {
            while (nextRow_ <= time + 1e-6 * deltaT)
            {
                nextRow_ += interval_;
            }
        }
    }
    double interval() const { return interval_; }
    const std::filesystem::path& folder() const { return folder_; }

private:
    double interval_;
    std::filesystem::path folder_;
    std::unique_ptr<DatFile> file_;
    double nextRow_ = 0.0;
};

} // namespace sph
