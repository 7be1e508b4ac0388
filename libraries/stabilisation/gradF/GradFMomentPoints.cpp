// gradF's stress samples at moment points (`samplePoints moments`,
// docs/theory/gradF-moments.md): each particle's points from its reference neighbourhood
// (MomentSamples), and gradF's refusal of what they cannot carry (§M4). Where the samples are
// used is GradF.cpp.
#include "core/InputError.hpp"
#include "particles/Parallel.hpp"
#include "stabilisation/gradF/GradF.hpp"

namespace sph
{

// The offsets x^r_ba and weights Ŵ_ab as kinematics() makes them (j = 0 the particle itself).
template <int D>
void MomentSamples<D>::prepare(const ReferenceConfiguration<D>& ref,
                               const std::vector<double>& invDenominator, std::size_t maxNeighbours)
{
    const NeighbourList& list = ref.neighbours;
    const std::size_t n = ref.size();
    points_.resize(active_ ? n * count : 0);
    weights_.resize(active_ ? n * count : 0);
    if (!active_)
    {
        return;
    }
#pragma omp parallel if (useThreads(n))
    {
        std::vector<Vec<D>> xr(maxNeighbours);
        std::vector<double> w(maxNeighbours);
#pragma omp for schedule(static)
        for (std::size_t a = 0; a < n; ++a)
        {
            const std::size_t first = list.begin(a);
            const std::size_t neighbours = list.count(a);
            const double* W = ref.kernelValues(a).W; // W[k - first] for slot k
            for (std::size_t j = 0; j < neighbours; ++j)
            {
                const std::size_t b = list.indices[first + j];
                xr[j] = j == 0 ? Vec<D>::Zero() : Vec<D>(ref.x[b] - ref.x[a]);
                w[j] = W[j] * ref.V[b] * invDenominator[a];
            }
            if (!momentPoints<D>(xr.data(), w.data(), neighbours, &points_[a * count],
                                 &weights_[a * count]))
            {
                weights_[a * count] = -1.0; // keeps its neighbour samples (§M2)
            }
        }
    }
}

template <int D>
void GradF<D>::refuseMovingMomentHistory(const std::vector<const Material<D>*>& materials) const
{
    if (!moments_.active() || !referenceMoves_)
    {
        return;
    }
    for (const Material<D>* material : materials)
    {
        if (material && material->hasHistory())
        {
            throw InputError(samplePointsWhere_,
                             "samplePoints moments with formulation updatedLagrangian and a "
                             "material with plastic history: each reference move makes new "
                             "points, and carrying a point's history to them is not derived "
                             "(docs/theory/gradF-moments.md §M4)",
                             {"hint: use formulation totalLagrangian with samplePoints moments, "
                              "or remove samplePoints (neighbours, the default)"});
        }
    }
}

template class MomentSamples<1>;
template class MomentSamples<2>;
template class MomentSamples<3>;
template void GradF<1>::refuseMovingMomentHistory(const std::vector<const Material<1>*>&) const;
template void GradF<2>::refuseMovingMomentHistory(const std::vector<const Material<2>*>&) const;
template void GradF<3>::refuseMovingMomentHistory(const std::vector<const Material<3>*>&) const;

} // namespace sph
