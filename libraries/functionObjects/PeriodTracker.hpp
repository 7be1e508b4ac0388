#pragma once
// Periods of an oscillating signal u(t) from its downward zero crossings (linear interpolation):
// the length of each complete cycle, the mean of u over it (trapezoidal rule, split at the
// crossings) and the largest |u| in it. Used by `exactSolution` (creep of the Dyka bar) and
// `oscillation` (the oscillating plate).

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace sph
{

class PeriodTracker
{
public:
    void add(double time, double u)
    {
        if (havePrevious_ && time > previousTime_)
        {
            if (previousU_ > 0.0 && u <= 0.0)
            {
                const double crossing =
                    previousTime_ + previousU_ * (time - previousTime_) / (previousU_ - u);
                integral_ += 0.5 * previousU_ * (crossing - previousTime_);
                if (lastCrossing_ >= 0.0)
                {
                    lastPeriod_ = crossing - lastCrossing_;
                    lastMean_ = integral_ / lastPeriod_;
                    lastAmplitude_ = amplitude_;
                    maxAbsMean_ = std::max(maxAbsMean_, std::abs(lastMean_));
                    if (periods_ == 0)
                    {
                        firstCrossing_ = lastCrossing_;
                        firstAmplitude_ = amplitude_;
                    }
                    ++periods_;
                }
                lastCrossing_ = crossing;
                integral_ = 0.5 * u * (time - crossing);
                amplitude_ = std::abs(u);
            }
            else
            {
                integral_ += 0.5 * (previousU_ + u) * (time - previousTime_);
            }
        }
        amplitude_ = std::max(amplitude_, std::abs(u));
        previousTime_ = time;
        previousU_ = u;
        havePrevious_ = true;
    }

    long periods() const { return periods_; }
    double lastPeriod() const { return lastPeriod_; }
    // Mean period over all complete cycles (first to last crossing).
    double meanPeriod() const
    {
        return periods_ > 0 ? (lastCrossing_ - firstCrossing_) / static_cast<double>(periods_) : 0.0;
    }
    double lastMean() const { return lastMean_; }
    double maxAbsMean() const { return maxAbsMean_; }
    double firstAmplitude() const { return firstAmplitude_; }
    double lastAmplitude() const { return lastAmplitude_; }

    void save(std::map<std::string, double>& state, const std::string& prefix) const
    {
        const double values[] = {previousTime_, previousU_, havePrevious_ ? 1.0 : 0.0,
                                 lastCrossing_, firstCrossing_, integral_, amplitude_,
                                 lastPeriod_, lastMean_, maxAbsMean_, firstAmplitude_,
                                 lastAmplitude_, static_cast<double>(periods_)};
        for (std::size_t i = 0; i < std::size(values); ++i)
        {
            state[prefix + std::to_string(i)] = values[i];
        }
    }
    void restore(const std::map<std::string, double>& state, const std::string& prefix)
    {
        double* fields[] = {&previousTime_, &previousU_, nullptr, &lastCrossing_, &firstCrossing_,
                            &integral_, &amplitude_, &lastPeriod_, &lastMean_, &maxAbsMean_,
                            &firstAmplitude_, &lastAmplitude_, nullptr};
        for (std::size_t i = 0; i < std::size(fields); ++i)
        {
            const double value = state.at(prefix + std::to_string(i));
            if (fields[i])
            {
                *fields[i] = value;
            }
            else if (i == 2)
            {
                havePrevious_ = value != 0.0;
            }
            else
            {
                periods_ = static_cast<long>(value);
            }
        }
    }

private:
    double previousTime_ = 0.0;
    double previousU_ = 0.0;
    bool havePrevious_ = false;
    double lastCrossing_ = -1.0;
    double firstCrossing_ = 0.0;
    double integral_ = 0.0;
    double amplitude_ = 0.0; // largest |u| since the last crossing
    double lastPeriod_ = 0.0;
    double lastMean_ = 0.0;
    double maxAbsMean_ = 0.0;
    double firstAmplitude_ = 0.0;
    double lastAmplitude_ = 0.0;
    long periods_ = 0;
};

} // namespace sph
