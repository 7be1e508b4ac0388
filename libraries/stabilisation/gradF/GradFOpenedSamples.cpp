// gradF's openedSamples particle (docs/theory/gradF-plastic.md §G22): at a move, the samples
// of a particle whose material has opened take that particle's state, and the energy they held
// is booked as dissipated. Called by moveHistory() (GradFMove.cpp) after the rebase.
#include "stabilisation/gradF/GradF.hpp"

#include <algorithm>
#include <cmath>

namespace sph
{

// openedSamples particle (§G22), after moveHistory()'s rebase: every particle's state as its
// own commit would make it at its current gradient (the return at its new frame F^r_b, where
// its rebased be is the one it has at x); where that state has opened, every sample of the
// particle takes it, re-expressed at the sampling particle's frame (G22.1). What the reset
// samples' energies fall by, under the quadrature Π had before the move, is kept per particle
// for the audit (G22.2).
template <int D>
void GradF<D>::takeOpenedStates(const std::vector<Vec<D>>& x, const ReferenceConfiguration<D>& ref,
                                const std::vector<int>& body,
                                const std::vector<Material<D>*>& materials)
{
    const NeighbourList& list = ref.neighbours;
    const std::size_t n = ref.size();
    const std::size_t stride = samples_.stride();
    std::vector<double> returned(n * stride);
    std::vector<std::uint8_t> opened(n, 0);
#pragma omp parallel for schedule(static) if (useThreads(n))
    for (std::size_t b = 0; b < n; ++b)
    {
        if (!spatialFrame_[b])
        {
            continue;
        }
        const Material<D>& material = *materials[static_cast<std::size_t>(body[b])];
        double committed[SampleHistory<D>::maxStride];
        material.packHistory(b, committed);
        const Mat<D> frame = movedFrames_[b] * Mat<D>::Identity();
        Mat<D> P;
        double psi;
        double dissipation;
        material.evaluate(&frame, &P, &psi, 1,
                          HistoryOf::samples(committed, stride, &returned[b * stride], &dissipation));
        opened[b] = material.opened(&returned[b * stride], frame) ? 1 : 0;
    }
#pragma omp parallel if (useThreads(n))
    {
        Scratch scratch;
        scratch.resize(maxNeighbours_);
        std::vector<Mat<D>> F;
        std::vector<Mat<D>> P;
        std::vector<double> before, after, states;
        std::vector<std::size_t> reset;
#pragma omp for schedule(static)
        for (std::size_t a = 0; a < n; ++a)
        {
            if (!spatialFrame_[a])
            {
                continue;
            }
            const std::size_t first = list.begin(a);
            const std::size_t count = list.count(a);
            reset.clear();
            for (std::size_t j = 0; j < count; ++j)
            {
                if (opened[list.indices[first + j]])
                {
                    reset.push_back(j);
                }
            }
            if (reset.empty())
            {
                continue;
            }
            const Material<D>& material = *materials[static_cast<std::size_t>(body[a])];
            const Mat<D> frame = movedFrames_[a] * Mat<D>::Identity();
            const std::size_t m = reset.size();
            F.assign(m, frame); // every sample's F_b(a) at the move (§G4)
            P.resize(m);
            before.resize(m);
            after.resize(m);
            states.resize(m * stride);
            for (std::size_t i = 0; i < m; ++i)
            {
                samples_.read(first + reset[i], 1, &states[i * stride]);
            }
            material.evaluate(F.data(), P.data(), before.data(), m,
                              HistoryOf::samples(states.data(), stride));
            for (std::size_t i = 0; i < m; ++i)
            {
                const std::size_t b = list.indices[first + reset[i]];
                double* state = &states[i * stride];
                std::copy(&returned[b * stride], &returned[(b + 1) * stride], state);
                material.rebaseHistory(state, movedFrames_[b] * Mat<D>::Identity(), frame);
                samples_.setState(first + reset[i], state);
            }
            material.evaluate(F.data(), P.data(), after.data(), m,
                              HistoryOf::samples(states.data(), stride));
            // The weights Π had before the move: the kept energy weights (§G9), else (and on a
            // first layout) the old reference's kernel weights.
            kinematics(a, x, ref, true, scratch);
            double fall = 0.0;
            for (std::size_t i = 0; i < m; ++i)
            {
                const std::size_t k = first + reset[i];
                const bool kept = samples_.weighted() && !std::isnan(samples_.weight(k));
                fall += (kept ? samples_.weight(k) : scratch.w[reset[i]]) * (before[i] - after[i]);
            }
            openingDissipation_[a] = ref.V[a] / ref.F[a].determinant() * fall; // V0_a = V^r_a / J^r_a
        }
    }
}

template <int D>
double GradF<D>::moveDissipation(const std::vector<std::uint8_t>* owned) const
{
    double total = 0.0;
    for (std::size_t a = 0; a < openingDissipation_.size(); ++a)
    {
        if (!owned || (*owned)[a])
        {
            total += openingDissipation_[a];
        }
    }
    return total;
}

template void GradF<1>::takeOpenedStates(const std::vector<Vec<1>>&, const ReferenceConfiguration<1>&,
                                          const std::vector<int>&, const std::vector<Material<1>*>&);
template void GradF<2>::takeOpenedStates(const std::vector<Vec<2>>&, const ReferenceConfiguration<2>&,
                                          const std::vector<int>&, const std::vector<Material<2>*>&);
template void GradF<3>::takeOpenedStates(const std::vector<Vec<3>>&, const ReferenceConfiguration<3>&,
                                          const std::vector<int>&, const std::vector<Material<3>*>&);
template double GradF<1>::moveDissipation(const std::vector<std::uint8_t>*) const;
template double GradF<2>::moveDissipation(const std::vector<std::uint8_t>*) const;
template double GradF<3>::moveDissipation(const std::vector<std::uint8_t>*) const;

} // namespace sph
