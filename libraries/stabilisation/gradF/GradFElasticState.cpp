// gradF's plasticSamples elasticState (docs/theory/gradF-plastic.md): what a move of the
// reference configuration does to the samples' states and the particles' own. The samples'
// evaluation and commit are those of every per-sample history (GradFHistory.cpp); the frame
// F^r = J^(1/D) I and K = 0 are set by referenceUpdate (GradF.cpp) for the particles marked here.
#include "stabilisation/gradF/GradF.hpp"

#include <cmath>
#include <stdexcept>

namespace sph
{

// elasticState (docs/theory/gradF-plastic.md §G4): with the old reference still in place, each
// sample's state and the particle's own are re-expressed against the new reference gradient,
// the dilation F^r_a = J_a^(1/D) I, so that their be at the current positions does not change
// (G4.1); the referenceUpdate() that follows sets that F^r_a and K_a = 0 for these particles.
template <int D>
void GradF<D>::moveHistory(const std::vector<Vec<D>>& x, const ReferenceConfiguration<D>& ref,
                           const std::vector<int>& body, const std::vector<Material<D>*>& materials)
{
    if (!elasticState_ || !samples_.active())
    {
        return;
    }
    const NeighbourList& list = ref.neighbours;
    const std::size_t n = ref.size();
    if (!samples_.current())
    {
        throw std::logic_error("gradF: the reference moves before the samples' states follow its "
                               "list (a move must come after a force evaluation)");
    }
    spatialFrame_.assign(n, 0);
#pragma omp parallel if (useThreads(n))
    {
        Scratch scratch;
        scratch.resize(maxNeighbours_);
#pragma omp for schedule(static)
        for (std::size_t a = 0; a < n; ++a)
        {
            Material<D>& material = *materials[static_cast<std::size_t>(body[a])];
            if (!material.hasHistory())
            {
                continue;
            }
            spatialFrame_[a] = 1;
            const Kinematics kin = kinematics(a, x, ref, false, scratch);
            const Mat<D> frame = std::pow(kin.F.determinant(), 1.0 / D) * Mat<D>::Identity();
            const std::size_t first = list.begin(a);
            for (std::size_t j = 0; j < list.count(a); ++j)
            {
                const Mat<D> Fb = kin.F + kin.G.contract(scratch.xr[j]);
                material.rebaseHistory(samples_.committedForMove(first + j), Fb, frame);
            }
            material.rebaseParticleHistory(a, kin.F, frame);
        }
    }
}

// GradF<D> is instantiated in GradF.cpp; this member is defined here.
template void GradF<1>::moveHistory(const std::vector<Vec<1>>&, const ReferenceConfiguration<1>&,
                                     const std::vector<int>&, const std::vector<Material<1>*>&);
template void GradF<2>::moveHistory(const std::vector<Vec<2>>&, const ReferenceConfiguration<2>&,
                                     const std::vector<int>&, const std::vector<Material<2>*>&);
template void GradF<3>::moveHistory(const std::vector<Vec<3>>&, const ReferenceConfiguration<3>&,
                                     const std::vector<int>&, const std::vector<Material<3>*>&);

} // namespace sph
