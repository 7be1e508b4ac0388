// A test-only plugin (built by the test suite, never installed): a material registered from a
// library that the solver does not know, loaded through a case's `libs (...)`.
#include "materials/Material.hpp"

namespace sph
{

template <int D>
class PluginLinear : public MaterialModel<D, PluginLinear<D>>
{
public:
    static std::string description() { return "Test plugin: 1D linear bar, P = E (F - 1)."; }
    static Schema schema()
    {
        return Material<D>::commonSchema().add(Key::real("E", "Young's modulus [Pa]").positive());
    }
    PluginLinear(const Params& p, const typename Material<D>::Args&)
        : MaterialModel<D, PluginLinear<D>>(p), E_(p.real("E"))
    {
    }
    Mat<D> stressOf(const Mat<D>& F) const { return Mat<D>::Constant(E_ * (F(0, 0) - 1.0)); }
    double energyOf(const Mat<D>& F) const { return 0.5 * E_ * (F(0, 0) - 1.0) * (F(0, 0) - 1.0); }
    double waveSpeedOf(const Mat<D>&) const { return std::sqrt(E_ / this->density()); }
    double youngsModulus() const override { return E_; }

private:
    double E_;
};

SPH_REGISTER_DIM_MODEL_FOR(Material, PluginLinear, "pluginLinear", 1);

} // namespace sph
