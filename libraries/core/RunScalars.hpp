#pragma once
// Run-level numbers that a restart needs (Δt state, energy-audit sums, the step of the last
// reference update, ...), each declared once by its owner, which binds its own member:
//
//   scalars.bind("previousDeltaT", previousDeltaT_);
//
// The output writes every bound scalar and a restart reads every one back (solver/StateFile).
// A model whose restart state is not per particle (the gradient-of-F scheme's per-pair plastic
// history) binds a run array instead: any length, written and read back whole.
//
//   scalars.bindArray("sampleHistory", states_);

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

    struct Array
    {
        std::string name;
        std::vector<double>* values;
    };
    void bindArray(const std::string& name, std::vector<double>& values);
    const std::vector<Array>& arrays() const { return arrays_; }

private:
    void add(const std::string& name, std::variant<double*, long*, bool*> value);
    void checkUnique(const std::string& name) const;
    std::vector<Scalar> scalars_;
    std::vector<Array> arrays_;
};

} // namespace sph
