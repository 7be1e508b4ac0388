#pragma once
// When something is written during a run: the VTK output, every function object's rows, the
// snapshots. One rule for all of them: at the first time level at or after each multiple of
// the interval (every level when the interval is 0), with a tolerance of 1e-6 of the step for
// the round-off in the accumulated time. With controlDict's `writeControl adjustableRunTime`
// (the default) the solver shortens the steps before each of these times (nextAfter()), so
// that the level lands on it exactly.

#include "Format.hpp"
#include "InputError.hpp"
#include "SourceLocation.hpp"

#include <cmath>
#include <limits>

namespace sph
{

class WriteSchedule
{
public:
    // `where`: the interval's entry in the case, for the error of checkStep().
    explicit WriteSchedule(double interval = 0.0, SourceLocation where = {})
        : interval_(interval), where_(std::move(where))
    {
    }

    // Round-off counts as on time: 1e-6 of the step, or 1e-12 of the time itself for the last
    // level, where no step follows (deltaT = 0) and the run stopped at endTime within
    // round-off (0.9999999999999999 for 1).
    bool due(double time, double deltaT) const
    {
        return interval_ <= 0.0 || time >= next_ - 1e-6 * deltaT - 1e-12 * std::abs(next_);
    }
    // After a write at `time`: the next multiple of the interval after it.
    void written(double time, double deltaT)
    {
        if (interval_ <= 0.0)
        {
            return;
        }
        // Bounded: an interval far below the step (or below the resolution of the time) must
        // not loop for ever; checkStep() reports it as an input error first.
        for (int passes = 0; next_ <= time + 1e-6 * deltaT; ++passes)
        {
            if (passes == 1000000 || next_ + interval_ == next_)
            {
                next_ = time + interval_;
                break;
            }
            next_ += interval_;
        }
    }
    // An interval shorter than the time step asks for more than one write per step: an input
    // error at the interval's entry (checked once Δt is known).
    void checkStep(double deltaT, const std::string& key = "writeInterval") const
    {
        if (interval_ > 0.0 && deltaT > 0.0 && interval_ < deltaT)
        {
            throw InputError(where_,
                             key + " " + formatNumber(interval_) +
                                 " s is shorter than the time step " + formatNumber(deltaT) +
                                 " s: that would be more than one output per step",
                             {"Outputs are written at most once per step: give an interval of "
                              "at least the time step (function objects: 0 writes every step).",
                              "The time step is courant h / c, c the largest wave speed of the "
                              "materials: check E and rho if it is not what you expect."});
        }
    }
    // The first write time after the level at `time`: next() unless a write is due at this
    // level, then the one written() would set. +inf when the interval is 0 (every level):
    // such a schedule asks for no particular time (writeControl adjustableRunTime).
    double nextAfter(double time, double deltaT) const
    {
        if (interval_ <= 0.0 || interval_ < deltaT)
        {
            // An interval below the step is reported by checkStep(); landing on it would
            // make steps of the interval's length.
            return std::numeric_limits<double>::infinity();
        }
        if (!due(time, deltaT))
        {
            return next_;
        }
        WriteSchedule after(*this);
        after.written(time, deltaT);
        return after.next_;
    }
    void restart() { next_ = 0.0; }
    double interval() const { return interval_; }
    // The next write time, as a restart saves and restores it.
    double& next() { return next_; }
    double next() const { return next_; }

private:
    double interval_;
    SourceLocation where_;
    double next_ = 0.0;
};

} // namespace sph
