// gradF's elasticState samples in total-Lagrangian form (docs/theory/gradF-plastic.md §G25):
// the samples of the step's increment in their particle's frame (G25.1), and the frames moved
// at each commit with every sample's elastic state kept. The frames themselves are
// SampleFrames.hpp; the force (G25.2) is GradF.cpp's with M_ab and z_ab.
#include "stabilisation/gradF/GradF.hpp"

#include <stdexcept>

namespace sph
{

template <int D>
void GradF<D>::fillFramedSamples(std::size_t a, const NeighbourList& list, const Kinematics& kin,
                                 Scratch& scratch) const
{
    frames_.offsets(a, list, scratch.xr.data(), scratch.M.data());
    SampleFrames<D>::samples(kin.F, kin.G, scratch.xr.data(), scratch.M.data(), list.count(a),
                             scratch.F.data());
}

// After the commit of the last evaluation's states: each sample's state re-expressed at the
// evaluation's F_a, Cp⁻¹ ← N Cp⁻¹ Nᵀ with N = F_a⁻¹ F_b(a) (G4.1), so that its be does not
// change, and the frames moved to that evaluation. Every sample keeps a record from then on.
template <int D>
void GradF<D>::moveSampleFrames(const HistoryCommit<D>& in)
{
    if (!framedList_)
    {
        throw std::logic_error("gradF: a commit before any force evaluation (§G25 frames)");
    }
    const NeighbourList& list = *framedList_;
    const std::size_t n = list.particleCount();
    if (!frames_.hasEvaluation(n))
    {
        throw std::logic_error("gradF: the frames' evaluation is not of the committed particles");
    }
    std::vector<int> body(n, -1);
    for (std::size_t b = 0; b < in.bodies.size(); ++b)
    {
        for (std::size_t a = in.bodies[b].begin; a < in.bodies[b].end; ++a)
        {
            body[a] = static_cast<int>(b);
        }
    }
    samples_.storeEveryState(body, in.materials);
#pragma omp parallel if (useThreads(n))
    {
        Scratch scratch;
        scratch.resize(maxNeighbours_);
#pragma omp for schedule(static)
        for (std::size_t a = 0; a < n; ++a)
        {
            const Material<D>* material = in.materials[static_cast<std::size_t>(body[a])];
            if (!material || !material->hasHistory())
            {
                continue;
            }
            const std::size_t count = list.count(a);
            frames_.offsets(a, list, scratch.xr.data(), scratch.M.data());
            SampleFrames<D>::samples(frames_.evaluatedF(a), frames_.evaluatedG(a),
                                     scratch.xr.data(), scratch.M.data(), count, scratch.F.data());
            scratch.states.resize(count * samples_.stride());
            samples_.rebase(list.begin(a), count, *material, scratch.F.data(),
                            frames_.evaluatedF(a), scratch.states.data());
        }
    }
    frames_.move();
}

template void GradF<1>::fillFramedSamples(std::size_t, const NeighbourList&, const Kinematics&,
                                          Scratch&) const;
template void GradF<2>::fillFramedSamples(std::size_t, const NeighbourList&, const Kinematics&,
                                          Scratch&) const;
template void GradF<3>::fillFramedSamples(std::size_t, const NeighbourList&, const Kinematics&,
                                          Scratch&) const;
template void GradF<1>::moveSampleFrames(const HistoryCommit<1>&);
template void GradF<2>::moveSampleFrames(const HistoryCommit<2>&);
template void GradF<3>::moveSampleFrames(const HistoryCommit<3>&);

} // namespace sph
