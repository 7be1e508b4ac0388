#include "particles/Parallel.hpp"
#include "stabilisation/hourglass/Hourglass.hpp"

namespace sph
{

template <int D>
std::string Hourglass<D>::description()
{
    return "Ganzenmueller (2015) hourglass control: pairwise penalty on the error of the "
           "F-predicted bond, parameter alpha (spec §5.2). Not derived from an energy. Acts in "
           "total-Lagrangian form; updated-Lagrangian with referenceUpdateInterval 1 makes the "
           "bond error zero at every step (then it is 'none'); with a lagging reference it turns "
           "unstable under rotation or stretch once alpha x interval is large (measured: alpha "
           "10 with interval 3, alpha 1 with interval 10; tutorials/hardCases/README.md).";
}

template <int D>
Schema Hourglass<D>::schema()
{
    return Schema().add(Key::real("alpha", "hourglass stiffness alpha_HG (dimensionless; 10-50 "
                                           "usual, problem dependent)")
                            .nonNegative()
                            .defaultValue("10"));
}

template <int D>
Hourglass<D>::Hourglass(const Params& params, const typename Stabilisation<D>::Args&)
    : alpha_(params.real("alpha"))
{
}

template <int D>
Vec<D> Hourglass<D>::hourglassForce(std::size_t a, const ForceInput<D>& in,
                                    const std::vector<Mat<D>>& f) const
{
    const NeighbourList& list = in.ref.neighbours;
    const double E = in.materials[static_cast<std::size_t>(in.body[a])]->youngsModulus();
    Vec<D> force = Vec<D>::Zero();
    const double* W = in.ref.kernelValues(a).W; // W[k - begin] for slot k
    for (std::size_t k = list.begin(a) + 1; k < list.end(a); ++k)
    {
        const std::size_t b = list.indices[k];
        const Vec<D> xr = in.ref.x[b] - in.ref.x[a];
        const Vec<D> xc = in.x[b] - in.x[a];
        const double length = xc.norm();
        const double referenceLength2 = xr.squaredNorm();
        if (length <= 0.0 || referenceLength2 <= 0.0 || W[k - list.begin(a)] == 0.0)
        {
            continue;
        }
        const Vec<D> unit = xc / length;
        const Vec<D> gamma = 0.5 * (f[a] + f[b]) * xr - xc;
        const double delta = 0.5 * gamma.dot(unit);
        force -= (alpha_ * E * in.V0[a] * in.V0[b] * W[k - list.begin(a)] * delta / referenceLength2) * unit;
    }
    return force;
}

template <int D>
ForceStatus Hourglass<D>::computeForces(const ForceInput<D>& in, ForceOutput<D>& out,
                                        bool wantEnergy)
{
    ForceStatus status = core_.compute(in, out, wantEnergy, StandardGradients<D>{in.ref}, &f_);
    if (!status.ok() || alpha_ == 0.0)
    {
        return status;
    }
    const std::size_t n = in.ref.size();
#pragma omp parallel for schedule(static) if (useThreads(n))
    for (std::size_t a = 0; a < n; ++a)
    {
        out.T[a] += hourglassForce(a, in, f_);
    }
    checkForces<D>(out.T, status, in.owned);
    return status;
}

template class Hourglass<1>;
template class Hourglass<2>;
template class Hourglass<3>;

SPH_REGISTER_DIM_MODEL(Stabilisation, Hourglass, "hourglass");

} // namespace sph
