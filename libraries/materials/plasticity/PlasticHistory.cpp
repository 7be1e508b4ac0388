#include "materials/plasticity/PlasticHistory.hpp"

namespace sph
{

namespace
{

// The names are those of the restart files written since j2Plasticity: keep them.
const FieldSpec& inversePlasticField()
{
    static const FieldSpec spec =
        FieldSpec::tensor("inversePlasticCauchyGreen",
                          "Cp^-1 = Fp^-1 Fp^-T of the last committed level (in-plane block)")
            .restart()
            .padding(TensorPadding::identity);
    return spec;
}
const FieldSpec& inversePlasticZZField()
{
    static const FieldSpec spec =
        FieldSpec::scalar("inversePlasticCauchyGreenZZ",
                          "zz component of Cp^-1 of the last committed level (2D plane strain)")
            .restart();
    return spec;
}
const FieldSpec& flowPressureField()
{
    static const FieldSpec spec =
        FieldSpec::scalar("plasticFlowPressure",
                          "mean stress at which the last commit flowed, 1e300 if it did not; "
                          "sphSolid before 2026-11-29 did not keep it")
            .restart();
    return spec;
}
const FieldSpec& committedAlphaField()
{
    static const FieldSpec spec =
        FieldSpec::scalar("equivalentPlasticStrain",
                          "equivalent plastic strain alpha of the last committed level")
            .restart();
    return spec;
}

} // namespace

template <int D>
const FieldSpec& PlasticHistory<D>::plasticStrainField()
{
    static const FieldSpec spec =
        FieldSpec::scalar("plasticStrain", "equivalent plastic strain alpha at this level")
            .display();
    return spec;
}

template <int D>
const FieldSpec& PlasticHistory<D>::yieldingField()
{
    static const FieldSpec spec =
        FieldSpec::integer("yielding", "1 where the particle flows plastically at this level")
            .display();
    return spec;
}

template <int D>
std::vector<FieldSpec> PlasticHistory<D>::fields()
{
    std::vector<FieldSpec> specs{inversePlasticField()};
    if constexpr (D == 2)
    {
        specs.push_back(inversePlasticZZField());
    }
    specs.push_back(flowPressureField());
    specs.push_back(committedAlphaField());
    specs.push_back(plasticStrainField());
    specs.push_back(yieldingField());
    return specs;
}

template <int D>
PlasticHistory<D>::PlasticHistory(const typename Material<D>::Args& args)
{
    ParticleFields<D>* fields = args.fields;
    if (!fields)
    {
        ownFields_ = std::make_unique<ParticleFields<D>>();
        ownFields_->setSize(args.particles.end);
        fields = ownFields_.get();
    }
    registry_ = fields;
    inversePlastic_ = &fields->template declare<Mat<D>>(inversePlasticField(), Mat<D>::Identity());
    if constexpr (D == 2)
    {
        inversePlasticZZ_ = &fields->template declare<double>(inversePlasticZZField(), 1.0);
    }
    flowPressure_ = &fields->template declare<double>(flowPressureField(), noFlowPressure);
    alpha_ = &fields->template declare<double>(committedAlphaField(), 0.0);
}

template <int D>
void PlasticHistory<D>::store(std::size_t a, const PlasticState<D>& s)
{
    (*inversePlastic_)[a] = s.inversePlastic;
    if constexpr (D == 2)
    {
        (*inversePlasticZZ_)[a] = s.inversePlasticZZ;
    }
    (*flowPressure_)[a] = s.flowPressure;
    (*alpha_)[a] = s.alpha;
}

template struct PlasticState<1>;
template struct PlasticState<2>;
template struct PlasticState<3>;
template class PlasticHistory<1>;
template class PlasticHistory<2>;
template class PlasticHistory<3>;

} // namespace sph
