// gradF with a material that has plastic history (docs/theory/plasticity.md §P7): the stress
// samples around a particle evaluated from their own committed states (or, `plasticSamples
// linearised`, from the particle's with the return's tangent), and the commit of those states.
// The rest of the scheme, for every material, is GradF.cpp.
#include "stabilisation/gradF/GradF.hpp"

#include <stdexcept>

namespace sph
{

template <int D>
void GradF<D>::evaluateSamples(std::size_t a, const Material<D>& material, const NeighbourList& list,
                               std::size_t count, double* psi, Scratch& scratch, bool pending)
{
    if (!(linearised_ && material.hasHistory()))
    {
        material.evaluate(scratch.F.data(), scratch.P.data(), psi, count,
                          historyAround(a, material, list, pending ? &scratch : nullptr));
        return;
    }
    // Evaluation 2: P_tr(F_b) + dP_a + A_a : (F_b − F_a), W_tr(F_b) + dW_a + dP_a : (F_b − F_a).
    material.evaluate(scratch.F.data(), scratch.P.data(), psi, count, HistoryOf::trialOf(a));
    const PlasticCorrection<D> c = material.plasticCorrection(scratch.F[0], a);
    if (!c.flowing)
    {
        return;
    }
    for (std::size_t j = 0; j < count; ++j)
    {
        const Mat<D> dF = scratch.F[j] - scratch.F[0];
        const Eigen::Matrix<double, D * D, 1> dFv = Eigen::Map<const Eigen::Matrix<double, D * D, 1>>(
            Mat<D>(dF.transpose()).data());
        const Eigen::Matrix<double, D * D, 1> dPv = c.A * dFv; // row-major components
        Mat<D> dP;
        for (int i = 0; i < D * D; ++i)
        {
            dP(i / D, i % D) = dPv[i];
        }
        scratch.P[j] += c.dP + dP;
        if (psi)
        {
            psi[j] += c.dW + (c.dP.array() * dF.array()).sum();
        }
    }
}

template <int D>
HistoryOf GradF<D>::historyAround(std::size_t a, const Material<D>& material,
                                  const NeighbourList& list, Scratch* scratch)
{
    if (!material.hasHistory())
    {
        return HistoryOf::particles(a); // unused
    }
    if (!samples_.active())
    {
        throw std::logic_error("gradF: a material with history, but declareHistory() was not "
                               "called");
    }
    const std::size_t k = list.begin(a);
    return scratch ? HistoryOf::samples(samples_.committed(k), samples_.stride(),
                                        samples_.next(k), scratch->dissipation.data())
                   : HistoryOf::samples(samples_.committed(k), samples_.stride());
}

// The particles' own states (each = its sample a–a: F_a(a) = F_a) for display and as the
// start of new pairs, then the samples' states; the dissipation is that of the samples.
template <int D>
double GradF<D>::commitHistory(const HistoryCommit<D>& in)
{
    if (linearised_)
    {
        return commitParticleHistory(in); // one state per particle, committed at F_a
    }
    commitParticleHistory(in);
    samples_.commit();
    double total = 0.0;
    for (std::size_t b = 0; b < in.bodies.size(); ++b)
    {
        if (in.materials[b])
        {
            for (std::size_t a = in.bodies[b].begin; a < in.bodies[b].end; ++a)
            {
                if (!in.owned || (*in.owned)[a])
                {
                    total += sampleDissipation_[a]; // a ghost's counts on its own rank
                }
            }
        }
    }
    return total;
}

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

// GradF<D> is instantiated in GradF.cpp; these are its members defined here.
template void GradF<1>::evaluateSamples(std::size_t, const Material<1>&, const NeighbourList&,
                                         std::size_t, double*, Scratch&, bool);
template HistoryOf GradF<1>::historyAround(std::size_t, const Material<1>&, const NeighbourList&,
                                          Scratch*);
template double GradF<1>::commitHistory(const HistoryCommit<1>&);
template void GradF<1>::moveHistory(const std::vector<Vec<1>>&, const ReferenceConfiguration<1>&,
                                     const std::vector<int>&, const std::vector<Material<1>*>&);
template void GradF<2>::evaluateSamples(std::size_t, const Material<2>&, const NeighbourList&,
                                         std::size_t, double*, Scratch&, bool);
template HistoryOf GradF<2>::historyAround(std::size_t, const Material<2>&, const NeighbourList&,
                                          Scratch*);
template double GradF<2>::commitHistory(const HistoryCommit<2>&);
template void GradF<2>::moveHistory(const std::vector<Vec<2>>&, const ReferenceConfiguration<2>&,
                                     const std::vector<int>&, const std::vector<Material<2>*>&);
template void GradF<3>::evaluateSamples(std::size_t, const Material<3>&, const NeighbourList&,
                                         std::size_t, double*, Scratch&, bool);
template HistoryOf GradF<3>::historyAround(std::size_t, const Material<3>&, const NeighbourList&,
                                          Scratch*);
template double GradF<3>::commitHistory(const HistoryCommit<3>&);
template void GradF<3>::moveHistory(const std::vector<Vec<3>>&, const ReferenceConfiguration<3>&,
                                     const std::vector<int>&, const std::vector<Material<3>*>&);

} // namespace sph
