// gradF with a material that has plastic history (docs/theory/plasticity.md §P7): the stress
// samples around a particle evaluated from their own committed states (or, `plasticSamples
// linearised`, from the particle's with the return's tangent), and the commit of those states.
// The rest of the scheme, for every material, is GradF.cpp.
#include "stabilisation/gradF/GradF.hpp"

#include <algorithm>
#include <stdexcept>

namespace sph
{

template <int D>
void GradF<D>::evaluateSamples(std::size_t a, const Material<D>& material, std::size_t count,
                               double* psi, Scratch& scratch, bool pending)
{
    if (!(linearised_ && material.hasHistory()))
    {
        material.evaluate(scratch.F.data(), scratch.P.data(), psi, count,
                          historyAround(a, material, count, scratch, pending));
        if (pending && material.hasHistory())
        {
            samples_.keepPending(samples_.begin(a), count, scratch.nextStates.data(),
                                 scratch.changed.data());
        }
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
void GradF<D>::evaluateSampleGroup(std::size_t a, std::size_t group, const Material<D>& material,
                                   bool psi,
                                   Scratch* const* members, SampleGroupScratch& g)
{
    constexpr std::size_t count = MomentPoints<D>::count;
    const std::size_t total = group * count;
    const std::size_t stride = samples_.stride();
    const std::size_t rowLength = HistoryOf::rowLengthFor(total);
    if (g.states.size() < rowLength * stride)
    {
        g.states.resize(rowLength * stride);
    }
    if (g.next.size() < total * stride)
    {
        g.next.resize(total * stride);
    }
    for (std::size_t k = 0; k < group; ++k)
    {
        const std::size_t offset = k * count;
        std::copy(members[k]->F.begin(), members[k]->F.begin() + count, g.F + offset);
        samples_.readRows(samples_.begin(a + k), count, g.states.data() + offset, rowLength,
                          rowLength - offset);
    }
    material.evaluate(g.F, g.P, psi ? g.psi : nullptr, total,
                      HistoryOf::samplesInRows(g.states.data(), rowLength, stride, g.next.data(),
                                               g.dissipation, g.changed));
    for (std::size_t k = 0; k < group; ++k)
    {
        const std::size_t offset = k * count;
        samples_.keepPending(samples_.begin(a + k), count, g.next.data() + offset * stride,
                             g.changed + offset);
        Scratch& member = *members[k];
        std::copy(g.P + offset, g.P + offset + count, member.P.begin());
        std::copy(g.dissipation + offset, g.dissipation + offset + count,
                  member.dissipation.begin());
        if (psi)
        {
            std::copy(g.psi + offset, g.psi + offset + count, member.psi.begin());
        }
    }
}

template <int D>
HistoryOf GradF<D>::historyAround(std::size_t a, const Material<D>& material, std::size_t count,
                                  Scratch& scratch, bool pending)
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
    const std::size_t stride = samples_.stride();
    if (material.readsStatesInRows())
    {
        // In rows (the material reads each component of 16 samples at once), padded to whole
        // blocks of them with the initial state; at most half a block (the moment points) in
        // a half row, which the material reads in half as many lanes. (The buffers only grow:
        // resizing them down and up again, particle by particle, cleared the new part each
        // time.)
        // (The row's length from the particle's slots, not its samples: total-Lagrangian
        // moment points lie in the first slots of the neighbour list's, and a row of fewer
        // lanes returns them in other lanes, whose round-off differs in 3D.)
        const std::size_t rowLength = HistoryOf::rowLengthFor(samples_.entries(a));
        const auto atLeast = [](auto& buffer, std::size_t size)
        {
            if (buffer.size() < size)
            {
                buffer.resize(size);
            }
        };
        atLeast(scratch.states, rowLength * stride);
        samples_.readRows(samples_.begin(a), count, scratch.states.data(), rowLength);
        if (!pending)
        {
            return HistoryOf::samplesInRows(scratch.states.data(), rowLength, stride);
        }
        atLeast(scratch.nextStates, count * stride);
        atLeast(scratch.changed, count);
        return HistoryOf::samplesInRows(scratch.states.data(), rowLength, stride,
                                        scratch.nextStates.data(), scratch.dissipation.data(),
                                        scratch.changed.data());
    }
    scratch.states.resize(count * stride);
    samples_.read(samples_.begin(a), count, scratch.states.data());
    if (!pending)
    {
        return HistoryOf::samples(scratch.states.data(), stride);
    }
    scratch.nextStates.resize(scratch.states.size());
    scratch.changed.resize(count);
    return HistoryOf::samples(scratch.states.data(), stride, scratch.nextStates.data(),
                              scratch.dissipation.data(), scratch.changed.data());
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
    if (frames_.active())
    {
        moveSampleFrames(in); // §G25
    }
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

// GradF<D> is instantiated in GradF.cpp; these are its members defined here.
template void GradF<1>::evaluateSamples(std::size_t, const Material<1>&, std::size_t,
                                         double*, Scratch&, bool);
template HistoryOf GradF<1>::historyAround(std::size_t, const Material<1>&, std::size_t,
                                          Scratch&, bool);
template double GradF<1>::commitHistory(const HistoryCommit<1>&);
template void GradF<1>::evaluateSampleGroup(std::size_t, std::size_t, const Material<1>&,
                                             bool, Scratch* const*, SampleGroupScratch&);
template void GradF<2>::evaluateSamples(std::size_t, const Material<2>&, std::size_t,
                                         double*, Scratch&, bool);
template HistoryOf GradF<2>::historyAround(std::size_t, const Material<2>&, std::size_t,
                                          Scratch&, bool);
template double GradF<2>::commitHistory(const HistoryCommit<2>&);
template void GradF<2>::evaluateSampleGroup(std::size_t, std::size_t, const Material<2>&,
                                             bool, Scratch* const*, SampleGroupScratch&);
template void GradF<3>::evaluateSamples(std::size_t, const Material<3>&, std::size_t,
                                         double*, Scratch&, bool);
template HistoryOf GradF<3>::historyAround(std::size_t, const Material<3>&, std::size_t,
                                          Scratch&, bool);
template double GradF<3>::commitHistory(const HistoryCommit<3>&);
template void GradF<3>::evaluateSampleGroup(std::size_t, std::size_t, const Material<3>&,
                                             bool, Scratch* const*, SampleGroupScratch&);

} // namespace sph
