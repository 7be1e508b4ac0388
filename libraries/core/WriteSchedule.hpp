#pragma once
// When something is written during a run: the VTK output, every function object's rows, the
// snapshots. One rule for all of them: at the first time level at or after each multiple of
// the interval (every level when the interval is 0), with a tolerance of 1e-6 of the step for
// the round-off in the accumulated time.

namespace sph
{

class WriteSchedule
{
public:
    explicit WriteSchedule(double interval = 0.0) : interval_(interval) {}

    bool due(double time, double deltaT) const
    {
        return interval_ <= 0.0 || time >= next_ - 1e-6 * deltaT;
    }
    // After a write at `time`: the next multiple of the interval after it.
    void written(double time, double deltaT)
    {
        if (interval_ > 0.0)
        {
            while (next_ <= time + 1e-6 * deltaT)
            {
                next_ += interval_;
            }
        }
    }
    void restart() { next_ = 0.0; }
    double interval() const { return interval_; }
    // The next write time, as a restart saves and restores it.
    double& next() { return next_; }
    double next() const { return next_; }

private:
    double interval_;
    double next_ = 0.0;
};

} // namespace sph
