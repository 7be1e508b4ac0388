#pragma once
// The pieces of the logarithmic law without principal axes that depend on the dimension
// (docs/theory/plasticity.md §P12 in 3D, §P13 in 2D), one struct per dimension with the same
// three functions, so that ReturnMapPlasticity::returnWithoutAxes is written once:
//   components          how many components its strain has (StrainLanes: 4 in plane strain,
//                       6 in 3D);
//   strain              ε = ½ ln be, as the components of a symmetric tensor; inRange[i] = 1
//                       where lane i's form is valid (2D: every lane; 3D: where the isochoric
//                       part of be is within the series' range, TensorLanes.hpp);
//   largestAbsolute     max |τᵢ| of the Kirchhoff stress, for the wave-speed bound (P2.5);
//   writeFlowingStates  the flowing lanes' new states: exp(2ε) of the returned strain, pulled
//                       back to Cp⁻¹ (§P4 step 4).

#include "materials/plasticity/GatheredLanes.hpp"
#include "materials/plasticity/LanesResult.hpp"
#include "materials/plasticity/PlaneLanes.hpp"
#include "materials/plasticity/TensorLanes.hpp"

namespace sph
{

template <int D>
struct AxesFreeLaw;

// Plane strain (§P13): the in-plane block in closed form, ε_zz = ½ ln be_zz.
template <>
struct AxesFreeLaw<2>
{
    static constexpr int components = 4; // the strain's (StrainLanes)
    template <int N, class Gathered>
    static void strain(const Gathered& in, const Lane<N> (&be)[2][2], StrainLanes<N, 4>& strain,
                       Lane<N>& inRange)
    {
        planeLanes::logarithmicStrain<N>(be, in.trialZZ(), strain);
        inRange = Lane<N>::Ones();
    }

    template <int N>
    static Lane<N> largestAbsolute(const Lane<N> (&tau)[4])
    {
        return planeLanes::largestAbsolutePrincipal<N>(tau);
    }

    // exp(2ε) in lanes (PlaneLanes.hpp), kept where a lane flows.
    template <int N, class State>
    static void writeFlowingStates(const DeviatorLanes<N, 4>& returned, const Lane<N> (&finv)[2][2],
                                   LanesResult<2, N>& out)
    {
        Lane<N> returnedBe[2][2], returnedZZ;
        planeLanes::exponentialOfTwice<N>(returned, returnedBe, returnedZZ);
        lanes::writeFlowingStates<2, N, State>(
            finv, [&](int k, int l) -> const Lane<N>& { return returnedBe[k][l]; }, returnedZZ,
            out.flow, out.next);
    }
};

// 3D (§P12): ln be and exp(2ε) by their series on the tensor.
template <>
struct AxesFreeLaw<3>
{
    static constexpr int components = 6;
    template <int N, class Gathered>
    static void strain(const Gathered&, const Lane<N> (&be)[3][3], StrainLanes<N, 6>& strain,
                       Lane<N>& inRange)
    {
        SymmetricLanes<N> b;
        b[0] = be[0][0];
        b[1] = be[1][1];
        b[2] = be[2][2];
        b[3] = 0.5 * (be[0][1] + be[1][0]);
        b[4] = 0.5 * (be[0][2] + be[2][0]);
        b[5] = 0.5 * (be[1][2] + be[2][1]);
        tensorLanes::logarithmicStrain<N>(b, strain, inRange);
    }

    template <int N>
    static Lane<N> largestAbsolute(const SymmetricLanes<N>& tau)
    {
        return tensorLanes::largestAbsoluteEigenvalue<N>(tau);
    }

    // exp(2ε) by its series over every lane at once, kept where a lane flows.
    template <int N, class State>
    static void writeFlowingStates(const DeviatorLanes<N, 6>& returned, const Lane<N> (&finv)[3][3],
                                   LanesResult<3, N>& out)
    {
        constexpr int at[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
        SymmetricLanes<N> returnedBe;
        tensorLanes::exponentialOfTwice<N>(returned, returnedBe);
        lanes::writeFlowingStates<3, N, State>(
            finv, [&](int k, int l) -> const Lane<N>& { return returnedBe[at[k][l]]; },
            returnedBe[2], out.flow, out.next);
    }
};

} // namespace sph
