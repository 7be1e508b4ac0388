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
    if (carrying_ && axes_.size() != n)
    {
        throw std::logic_error("MomentSamples: axes of " + std::to_string(axes_.size()) +
                               " particles, a reference of " + std::to_string(n));
    }
    if (moving_ && targets_.size() != n)
    {
        throw std::logic_error("MomentSamples: a move of " + std::to_string(targets_.size()) +
                               " particles, a reference of " + std::to_string(n));
    }
#pragma omp parallel if (useThreads(n))
    {
        std::vector<Vec<D>> xr(std::max(maxNeighbours, count));
        std::vector<double> w(std::max(maxNeighbours, count));
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
            // Carrying states, a particle with fewer neighbours than points still has its
            // points wherever its covariance spans every direction (§M7): entries of weight 0
            // at the particle change no moment. (In total Lagrangian form such a particle keeps
            // its few neighbour samples, §M2.)
            std::size_t entries = neighbours;
            for (; carrying_ && entries < count; ++entries)
            {
                xr[entries] = Vec<D>::Zero();
                w[entries] = 0.0;
            }
            Vec<D>* points = &points_[a * count];
            if (!momentPoints<D>(xr.data(), w.data(), entries, points, &weights_[a * count]))
            {
                weights_[a * count] = -1.0; // keeps its neighbour samples (§M2)
                if (carrying_)
                {
                    axes_[a] = notYet(); // or samples alone; its next axes are Cholesky's (§M7)
                }
                continue;
            }
            if (!carrying_)
            {
                continue;
            }
            // §M7: a move turns the axes with the material (M7.2); a restart, or a new
            // layout of the same reference (a distributed run's), keeps them.
            const Mat<D>& kept = moving_ ? targets_[a] : axes_[a];
            if (!kept.allFinite())
            {
                axes_[a] = momentAxes<D>(points); // Cholesky's
                continue;
            }
            axes_[a] = moving_ ? carriedAxes<D>(momentAxes<D>(points), kept) : kept;
            turnMomentPoints<D>(points, axes_[a]);
        }
    }
    moving_ = false;
}

template <int D>
void GradF<D>::refuseMovingMomentHistory(const std::vector<const Material<D>*>& materials) const
{
    if (!moments_.active() || !referenceMoves_ || elasticState_)
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
                             "points, whose history only plasticSamples elasticState carries "
                             "to them (docs/theory/gradF-moments.md §M4, §M7)",
                             {"hint: add 'plasticSamples elasticState;' to stabilisation, use "
                              "formulation totalLagrangian, or remove samplePoints (neighbours, "
                              "the default)"});
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
