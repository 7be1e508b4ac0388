#include "core/Format.hpp"
#include "particles/Parallel.hpp"
#include "stabilisation/vidal/Vidal.hpp"

namespace sph
{

template <int D>
std::string Vidal<D>::description()
{
    return "Stabilised corrected gradient with a vector parameter beta. This project's "
           "realisation of the idea the seed attributes to Vidal, Bonet & Huerta 2007 (their "
           "formula was not available): the corrected gradient of particle a is evaluated at "
           "x_a + h beta, keeping linear completeness (spec §5.1). beta = 0 is 'none'. Its "
           "stability map on the Dyka bar (tutorials/bar1D/vidalStabilityMap: h/dx x beta x "
           "kernel x resolution) finds no stable setting: 0 of 180 runs (gradF 33 of 36).";
}

template <int D>
Schema Vidal<D>::schema()
{
    return Schema().add(Key::vector("beta", "shift of the gradient's evaluation point in units "
                                            "of h (dimensionless, |beta| < 1)")
                            .defaultValue("0.1"));
}

template <int D>
Vidal<D>::Vidal(const Params& params, const typename Stabilisation<D>::Args& args)
    : kernel_(*args.kernel), beta_(toVec<D>(params.vector("beta")))
{
    if (!(beta_.norm() < 1.0))
    {
        params.fail("beta", "vidal: |beta| = " + formatNumber(beta_.norm()) + " must be below 1",
                    {"beta shifts the gradient's evaluation point by h*beta; keep it well inside "
                     "the kernel support."});
    }
}

namespace
{

template <int D>
Vec<D> kernelGradient(const Kernel& kernel, const Vec<D>& v)
{
    const double r = v.norm();
    return r > 0.0 ? Vec<D>((kernel.dWdr(r) / r) * v) : Vec<D>::Zero();
}

} // namespace

template <int D>
ForceStatus Vidal<D>::prepare(const ReferenceConfiguration<D>& ref)
{
    const NeighbourList& list = ref.neighbours;
    const std::size_t n = ref.size();
    const Vec<D> shift = kernel_.h() * beta_;
    resizePairArray(out_, list.pairCount());
    resizePairArray(in_, list.pairCount());
#pragma omp parallel for schedule(static) if (useThreads(n))
    for (std::size_t a = 0; a < n; ++a)
    {
        for (std::size_t k = list.begin(a); k < list.end(a); ++k)
        {
            const std::size_t b = list.indices[k];
            out_[k] = kernelGradient<D>(kernel_, Vec<D>(ref.x[a] + shift - ref.x[b]));
            in_[k] = kernelGradient<D>(kernel_, Vec<D>(ref.x[b] + shift - ref.x[a]));
        }
    }
    const long singular = corrected_.build(list, ref.x, ref.V,
                                           [this](std::size_t) {
                                               return [this](std::size_t k) { return out_[k]; };
                                           },
                                           ref.owned);
    return singular < 0 ? ForceStatus{}
                        : ForceStatus::failed(FailureKind::singularReference, singular, 0.0,
                                              "shifted corrected-gradient matrix (too few "
                                              "neighbours in x^r)");
}

template class Vidal<1>;
template class Vidal<2>;
template class Vidal<3>;

SPH_REGISTER_DIM_MODEL(Stabilisation, Vidal, "vidal");

} // namespace sph
