// gradF's precomputations from the reference configuration (spec §6.2): the normalised kernel
// weights' denominators, the least-squares matrices Z_a⁻¹ (or the joint fit's A_a⁻¹), s_a, Y_a,
// and the moment points (GradFMomentPoints.cpp). The force is GradF.cpp.
#include "particles/Parallel.hpp"
#include "stabilisation/gradF/GradF.hpp"
#include "stabilisation/gradF/MonomialTensors.hpp"
#include "stabilisation/gradF/RegularisedInverse.hpp"

#include <cmath>

namespace sph
{

template <int D>
ForceStatus GradF<D>::prepare(const ReferenceConfiguration<D>& ref)
{
    const NeighbourList& list = ref.neighbours;
    const std::size_t n = ref.size();
    invDenominator_.resize(n);
    s_.resize(n);
    // Z⁻¹ and Y are the sequential fit's; the joint fit keeps A⁻¹ instead (432 B per particle
    // in 3D not held).
    Zinv_.resize(jointFit_ ? 0 : n);
    Y_.resize(jointFit_ ? 0 : n);
    maxNeighbours_ = list.maxCount();
    samples_.listChanged();
    if (jointFit_)
    {
        Ainv_.resize(n);
        firstMoment_.resize(n);
        jointComplement_.resize(n);
    }
    long singular = -1;
#pragma omp parallel for schedule(static) reduction(max : singular) if (useThreads(n))
    for (std::size_t a = 0; a < n; ++a)
    {
        const std::size_t first = list.begin(a);
        const double* W = ref.kernelValues(a).W; // W[k - first] for slot k
        double denominator = 0.0;
        for (std::size_t k = first; k < list.end(a); ++k)
        {
            denominator += W[k - first] * ref.V[list.indices[k]];
        }
        invDenominator_[a] = 1.0 / denominator;
        MatM Z = MatM::Zero();
        MonomialVec<D> s = MonomialVec<D>::Zero();
        MatMD Y = MatMD::Zero();
        Mat<D> Mxx = Mat<D>::Zero(); // fit joint: Σ Ŵ x^r ⊗ x^r
        Vec<D> moment = Vec<D>::Zero();
        for (std::size_t k = list.begin(a) + 1; k < list.end(a); ++k)
        {
            const Vec<D> xr = ref.x[list.indices[k]] - ref.x[a];
            const MonomialVec<D> z = monomials<D>(xr);
            const double w = W[k - first] * ref.V[list.indices[k]] * invDenominator_[a]; // Ŵ_ak
            Z.noalias() += w * z * z.transpose();
            s += w * z;
            Y.noalias() += w * z * xr.transpose();
            if (jointFit_)
            {
                Mxx.noalias() += (w * xr) * xr.transpose();
                moment += w * xr;
            }
        }
        if (jointFit_)
        {
            firstMoment_[a] = moment;
            jointComplement_[a] = invertJointMatrix(Mxx, Y, Z, Ainv_[a]);
        }
        // Z is SPD with at least M non-degenerate neighbours; judge it scale-free.
        const double scale = Z.trace() / M;
        const double det = (Z / scale).determinant();
        if ((!(scale > 0.0) || !(det > 1.0e-12) || !std::isfinite(det)) && ref.counts(a))
        {
            singular = std::max<long>(singular, static_cast<long>(n - a));
        }
        s_[a] = s;
        if (!jointFit_)
        {
            Zinv_[a] = regularisedInverse(Z, scale, smallestEigenvalue);
            Y_[a] = Y;
        }
    }
    moments_.prepare(ref, invDenominator_, maxNeighbours_);
    if (singular < 0)
    {
        return {};
    }
    return ForceStatus::failed(FailureKind::singularReference, static_cast<long>(n) - singular,
                               0.0, "least-squares matrix Z (too few neighbours in x^r)");
}

template ForceStatus GradF<1>::prepare(const ReferenceConfiguration<1>&);
template ForceStatus GradF<2>::prepare(const ReferenceConfiguration<2>&);
template ForceStatus GradF<3>::prepare(const ReferenceConfiguration<3>&);

} // namespace sph
