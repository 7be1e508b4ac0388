#pragma once
// The paths through ReturnMapPlasticity's return in lanes (ReturnMapLanes.hpp): evaluate (a
// body's stress samples, with their states; a chunk of particles, with the memo), and the
// particles' own returns the memo does not hold (the wave speed, the commit). Included at the
// end of ReturnMapPlasticity.hpp, whose members it defines.

#include "materials/plasticity/ReturnMapLanes.hpp"

#include <bit>
#include <cstdint>
#include <stdexcept>

namespace sph
{

template <int D, class Model>
void ReturnMapPlasticity<D, Model>::evaluate(const Mat<D>* F, Mat<D>* P, double* psi, std::size_t n,
                                             HistoryOf history) const
{
    for (std::size_t i = 0; i < n;)
    {
        if constexpr (D >= 2)
        {
            const std::size_t count = std::min(lanes, n - i);
            if (history.perSample())
            {
                // (The states from i on are addressed through `history` and i: a copy of it per
                // block, changed number by number and read back whole, waited on its stores.)
                // A block of at most half the lanes (gradF's moment points, 5 in 2D and 7 in
                // 3D; a neighbour list's last block) in half as many: a lane's result does not
                // depend on the width (ReturnLanes.hpp).
                if (count <= lanes / 2)
                {
                    evaluateSamplesInLanes<lanes / 2>(F + i, P + i, psi ? psi + i : nullptr, count,
                                                      history, i);
                }
                else
                {
                    evaluateSamplesInLanes<lanes>(F + i, P + i, psi ? psi + i : nullptr, count,
                                                  history, i);
                }
                i += count;
                continue;
            }
            if (!history.trialAround)
            {
                evaluateParticlesInLanes(F + i, P + i, psi ? psi + i : nullptr, count,
                                         history.particle(i));
                i += count;
                continue;
            }
        }
        // The bar, and the trial (elastic predictor) around one particle: point by point.
        if (history.inRows())
        {
            throw std::logic_error("ReturnMapPlasticity: states in rows in 1D");
        }
        const bool perSample = history.perSample();
        const State s = perSample ? State::unpack(history.states + i * history.stride)
                                  : state(history.particle(i));
        const bool flow = perSample || !history.trialAround;
        const bool wantNext = perSample ? history.next != nullptr : flow;
        const Result r = returnMap(F[i], s, wantNext, flow);
        P[i] = r.P;
        if (psi)
        {
            psi[i] = r.energy;
        }
        if (!perSample && flow)
        {
            memo_.store(history.particle(i), F[i], s, {r.waveModulus, r.flow, r.next});
        }
        if (perSample && wantNext)
        {
            const double* committed = history.states + i * history.stride;
            double* next = history.next + i * history.nextStride;
            if (r.flow.deltaGamma > 0.0)
            {
                r.next.pack(next);
            }
            else
            {
                std::copy(committed, committed + State::packedSize, next);
                next[State::flowPressureAt] = noFlowPressure;
            }
            if (history.changed)
            {
                history.changed[i] = 1; // (written either way: the 1D bar's rare path)
            }
            history.dissipation[i] = r.flow.dissipation;
        }
        ++i;
    }
}

template <int D, class Model>
void ReturnMapPlasticity<D, Model>::evaluateParticlesInLanes(const Mat<D>* F, Mat<D>* P,
                                                             double* psi, std::size_t count,
                                                             std::size_t firstParticle) const
{
    if constexpr (D >= 2)
    {
        double states[lanes * State::packedSize];
        for (std::size_t i = 0; i < count; ++i)
        {
            state(firstParticle + i).pack(states + i * State::packedSize);
        }
        LanesResult<lanes> out;
        returnInLanes<lanes>(F, states, State::packedSize, count, true, {}, out);
        for (std::size_t i = 0; i < count; ++i)
        {
            const int lane = static_cast<int>(i);
            P[i] = out.stressAt(lane);
            if (psi)
            {
                psi[i] = out.energy[i];
            }
            memo_.store(firstParticle + i, F[i], State::unpack(states + i * State::packedSize),
                        {out.waveModulus[i], out.flowAt(lane), out.nextAt(lane)});
        }
    }
}

template <int D, class Model>
template <std::size_t N>
void ReturnMapPlasticity<D, Model>::evaluateSamplesInLanes(const Mat<D>* F, Mat<D>* P, double* psi,
                                                           std::size_t count,
                                                           const HistoryOf& history,
                                                           std::size_t first) const
{
    if constexpr (D >= 2)
    {
        const bool wantNext = history.next != nullptr;
        LanesResult<N> out;
        // A sample's wave modulus is never read (the time step takes the particles').
        returnInLanes<N>(F, history.states + history.at(first, 0), history.stride, count, true,
                         {wantNext, false, psi != nullptr}, out, history.componentStride);
        // Lane by lane into P, psi and the flags, each in a loop of its own (they vectorise;
        // one loop writing all of them per lane did not).
        const auto copyLanes = [count](const auto* from, auto* to)
        { copyFirst<static_cast<int>(N)>(from, to, count); };
        out.storeStresses(P, count);
        if (psi)
        {
            copyLanes(out.energy.data(), psi);
        }
        if (!wantNext)
        {
            return;
        }
        copyLanes(out.flow.dissipation.data(), history.dissipation + first);
        // A lane that does not flow keeps the committed state but for the flow pressure the
        // return gave it (keepCommitted): the committed state, bit for bit, where that is the
        // committed pressure. Only the others are written and compared.
        std::uint8_t changed[N];
        for (std::size_t lane = 0; lane < count; ++lane)
        {
            const double committedPressure =
                history.states[history.at(first + lane, State::flowPressureAt)];
            changed[lane] =
                out.flow.deltaGamma[static_cast<int>(lane)] > 0.0 ||
                        std::bit_cast<std::uint64_t>(out.flow.pressure[static_cast<int>(lane)]) !=
                            std::bit_cast<std::uint64_t>(committedPressure)
                    ? 1
                    : 0;
        }
        if (history.changed)
        {
            copyLanes(changed, history.changed + first);
        }
        for (std::size_t lane = 0; lane < count; ++lane)
        {
            if (changed[lane] || !history.changed)
            {
                out.packNext(static_cast<int>(lane),
                             history.next + (first + lane) * history.nextStride);
            }
        }
    }
}

template <int D, class Model>
void ReturnMapPlasticity<D, Model>::particleReturns(const Mat<D>* F, std::size_t first,
                                                    std::size_t n,
                                                    typename ReturnMemo<D>::Entry* out) const
{
    if constexpr (D == 1)
    {
        for (std::size_t i = 0; i < n; ++i)
        {
            out[i] = particleReturn(first + i, F[i], state(first + i));
        }
    }
    else
    {
        std::size_t missing[lanes];
        Mat<D> missingF[lanes];
        double states[lanes * State::packedSize];
        std::size_t count = 0;
        for (std::size_t i = 0; i < n; ++i)
        {
            const State s = state(first + i);
            if (!memo_.find(first + i, F[i], s, out[i]))
            {
                missing[count] = i;
                missingF[count] = F[i];
                s.pack(states + count * State::packedSize);
                ++count;
            }
        }
        if (count == 0)
        {
            return;
        }
        LanesResult<lanes> r;
        returnInLanes<lanes>(missingF, states, State::packedSize, count, true, {}, r);
        for (std::size_t j = 0; j < count; ++j)
        {
            const int lane = static_cast<int>(j);
            out[missing[j]] = {r.waveModulus[lane], r.flowAt(lane), r.nextAt(lane)};
        }
    }
}

} // namespace sph
