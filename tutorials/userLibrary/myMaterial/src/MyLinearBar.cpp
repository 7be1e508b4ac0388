// `myLinearBar`: a material of your own, compiled outside sphSolid and selected by name from
// constant/bodies once system/controlDict loads its library (libs ("lib/libmyModels.so");).
//
// The law is the bar's linear elasticity, P = E (F − 1), Ψ = ½ E (F − 1)², so that this case
// reproduces tutorials/bar1D/dykaBar (whose `linearElastic` is the same law) and you can check
// the plugin against it. Change stressOf/energyOf/waveSpeedOf to your law; MaterialModel
// supplies the loops over particles. The schema declares the keys: a case that misspells one,
// or gives E ≤ 0, stops with file:line and the valid choices, like every built-in model.
#include "materials/Material.hpp"

#include <cmath>

namespace myModels
{

using namespace sph;

template <int D>
class MyLinearBar : public MaterialModel<D, MyLinearBar<D>>
{
public:
    static std::string description() { return "My linear bar (1D): P = E (F - 1)."; }
    static Schema schema()
    {
        return Material<D>::commonSchema().add(Key::real("E", "Young's modulus [Pa]").positive());
    }
    MyLinearBar(const Params& params, const typename Material<D>::Args&)
        : MaterialModel<D, MyLinearBar<D>>(params), E_(params.real("E"))
    {
    }
    // First Piola–Kirchhoff stress, strain energy per unit initial volume, wave speed (for Δt).
    Mat<D> stressOf(const Mat<D>& F) const { return Mat<D>::Constant(E_ * (F(0, 0) - 1.0)); }
    double energyOf(const Mat<D>& F) const { return 0.5 * E_ * std::pow(F(0, 0) - 1.0, 2); }
    double waveSpeedOf(const Mat<D>&) const { return std::sqrt(E_ / this->density()); }
    double youngsModulus() const override { return E_; }

private:
    double E_;
};

// One line registers the model for 1D cases under the name the case uses.
SPH_REGISTER_DIM_MODEL_FOR(Material, MyLinearBar, "myLinearBar", 1);

} // namespace myModels
