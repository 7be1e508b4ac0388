// A test-only plugin (built by the test suite, never installed): a function object that keeps
// per-particle history — the largest speed each particle has had — in a field it declares
// itself. Nothing in the solver names it: the registry writes it to every output, a restart
// reads it back, and -listTypes lists it from `fields()`.
#include "functionObjects/FunctionObject.hpp"

#include <algorithm>

namespace sph
{

template <int D>
class PluginPeakSpeed : public FunctionObject<D>
{
public:
    static std::string description()
    {
        return "Test plugin: the largest speed each particle has had, as a per-particle field.";
    }
    static Schema schema() { return Schema(); }
    static const FieldSpec& peakSpeedField()
    {
        static const FieldSpec spec =
            FieldSpec::scalar("peakSpeed", "largest |v| the particle has had [m/s]")
                .restart()
                .display();
        return spec;
    }
    static std::vector<FieldSpec> fields() { return {peakSpeedField()}; }

    PluginPeakSpeed(const Params&, const typename FunctionObject<D>::Args& args)
        : FunctionObject<D>(args.name), peak_(args.fields->template declare<double>(peakSpeedField()))
    {
    }

    void start(double, bool) override {}
    // Taking the maximum at a level twice (a restart recomputes the level it starts from)
    // changes nothing, so the history written after the level is the one to restart from.
    void execute(const StepState<D>& state) override
    {
        for (std::size_t a = 0; a < peak_.size(); ++a)
        {
            peak_[a] = std::max(peak_[a], state.velocity[a].norm());
        }
    }

private:
    std::vector<double>& peak_;
};

SPH_REGISTER_DIM_MODEL(FunctionObject, PluginPeakSpeed, "pluginPeakSpeed");

} // namespace sph
