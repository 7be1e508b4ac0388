#pragma once
// Run-level numbers that a restart needs (Δt state, energy-audit sums, the step of the last
// reference update, ...), each declared once by its owner, which binds its own member:
//
//   scalars.bind("previousDeltaT", previousDeltaT_);
//
// The output writes every bound scalar and a restart reads every one back (solver/StateFile).

#include <string>
#include <variant>
#include <vector>

namespace sph
{

class RunScalars
{
public:
    void bind(const std::string& name, double& value) { add(name, &value); }
    void bind(const std::string& name, long& value) { add(name, &value); }
    void bind(const std::string& name, bool& value) { add(name, &value); }

    struct Scalar
    {
        std::string name;
        std::variant<double*, long*, bool*> value;
        double get() const;
        void set(double number) const;
    };
    const std::vector<Scalar>& all() const { return scalars_; }

private:
    void add(const std::string& name, std::variant<double*, long*, bool*> value);
    std::vector<Scalar> scalars_;
};

} // namespace sph
