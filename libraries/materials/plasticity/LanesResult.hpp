#pragma once
// What ReturnMapPlasticity's return map gives back at N points side by side
// (ReturnMapLanes.hpp): the stresses, energies, flows and wave moduli lane by lane, and the
// states a commit would write.

#include "materials/plasticity/PlasticHistory.hpp"
#include "materials/plasticity/ReturnLanes.hpp"

#include <algorithm>

namespace sph
{

// What a caller reads of a return in lanes besides the stresses and the flows: the states a
// commit would write, the wave modulus M + max |τ| (P2.5) and the energy W. What is not
// wanted is not computed (and its lanes are not meaningful).
struct LanesWanted
{
    bool next = true;
    bool waveModulus = true;
    bool energy = true;
};

template <int D, int N> struct LanesResult
{
    Lane<N> P[D][D];
    Lane<N> energy;
    FlowLanes<N> flow;
    Lane<N> waveModulus;
    Lane<N>
        next[PlasticState<D>::packedSize]; // (wantNext) the committed state where it does not flow

    Mat<D> stressAt(int i) const
    {
        Mat<D> result;
        for (int k = 0; k < D; ++k)
        {
            for (int l = 0; l < D; ++l)
            {
                result(k, l) = P[k][l][i];
            }
        }
        return result;
    }
    // P of the first `count` lanes into out[0 .. count) (through a block of all N, whose
    // transposition vectorises).
    void storeStresses(Mat<D>* out, std::size_t count) const
    {
        Mat<D> block[N];
        for (int i = 0; i < N; ++i)
        {
            for (int k = 0; k < D; ++k)
            {
                for (int l = 0; l < D; ++l)
                {
                    block[i](k, l) = P[k][l][i];
                }
            }
        }
        copyFirst<N>(block, out, count);
    }
    PlasticFlow flowAt(int i) const
    {
        return {flow.deltaGamma[i], flow.alpha[i], flow.dissipation[i], flow.pressure[i]};
    }
    void packNext(int i, double* out) const
    {
        for (std::size_t c = 0; c < PlasticState<D>::packedSize; ++c)
        {
            out[c] = next[c][i];
        }
    }
    // Lane i of `from` (every field) into lane i.
    void copyLane(const LanesResult& from, int i)
    {
        for (int k = 0; k < D; ++k)
        {
            for (int l = 0; l < D; ++l)
            {
                P[k][l][i] = from.P[k][l][i];
            }
        }
        energy[i] = from.energy[i];
        flow.deltaGamma[i] = from.flow.deltaGamma[i];
        flow.alpha[i] = from.flow.alpha[i];
        flow.dissipation[i] = from.flow.dissipation[i];
        flow.pressure[i] = from.flow.pressure[i];
        waveModulus[i] = from.waveModulus[i];
        for (std::size_t c = 0; c < PlasticState<D>::packedSize; ++c)
        {
            next[c][i] = from.next[c][i];
        }
    }
    // The state a memo entry holds: next, with the flow's α.
    PlasticState<D> nextAt(int i) const
    {
        double packed[PlasticState<D>::packedSize];
        packNext(i, packed);
        PlasticState<D> s = PlasticState<D>::unpack(packed);
        s.alpha = flow.alpha[i];
        return s;
    }
};

} // namespace sph
