#pragma once
// N points of the logarithmic law side by side (issue 30: plastic materials at the cost of
// elastic ones; docs/performance.md, "The return in lanes"). A gradF particle evaluates its
// 20-120 stress samples one after another; point by point, the return is a chain of square
// roots and divisions that waits on each result, and its branch "inside the cone or not",
// which a flowing deposit makes unpredictable, throws the work in flight away. In lanes every
// quantity is an array over N points (structure of arrays), every branch is computed both ways
// and one kept per lane, and the loops over lanes vectorise: N square roots in one
// instruction, no branch to mispredict.
//
// A model's return in lanes (ReturnMapPlasticity: `returnLanes`) is its only return: the
// point-by-point return is the same code with N = 1, so the two cannot drift apart. Lanes
// that do not flow come back with Δγ = 0, their strains and α unchanged, whatever the
// discarded branch computed for them (an infinity, a NaN: never kept).

#include <Eigen/Core>

#include <cmath>

namespace sph
{

template <int N>
using Lane = Eigen::Array<double, N, 1>;

// The three principal logarithmic strains of N points: eps[k][i] is point i's k-th.
template <int N>
struct StrainLanes
{
    Lane<N> eps[3];

    Eigen::Vector3d point(int i) const { return {eps[0][i], eps[1][i], eps[2][i]}; }
    void setPoint(int i, const Eigen::Vector3d& e)
    {
        for (int k = 0; k < 3; ++k)
        {
            eps[k][i] = e[k];
        }
    }
};

// N symmetric positive-definite D×D matrices (be) in principal form: the principal log
// strains (in 2D the third is zz's) and the directions, vectors[i][k] the i-th component of
// direction k.
template <int N, int D>
struct PrincipalLanes
{
    StrainLanes<N> strain;
    Lane<N> vectors[D][D];
};

// What a return did at N points (PlasticFlow's fields, lane by lane). pressure starts as
// noFlowPressure; a model that keeps a flow pressure sets it where the point flows.
template <int N>
struct FlowLanes
{
    Lane<N> deltaGamma;
    Lane<N> alpha;
    Lane<N> dissipation;
    Lane<N> pressure;
};

// The volumetric and deviatoric parts of N points' strains, computed as the point-by-point
// law always has: εv = (ε0 + ε1) + ε2, e = ε − εv/3, |e|.
template <int N>
struct DeviatorLanes
{
    Lane<N> volumetric;
    Lane<N> dev[3];
    Lane<N> norm;

    explicit DeviatorLanes(const StrainLanes<N>& s)
    {
        for (int i = 0; i < N; ++i)
        {
            const double ev = s.eps[0][i] + s.eps[1][i] + s.eps[2][i];
            const double d0 = s.eps[0][i] - ev / 3.0;
            const double d1 = s.eps[1][i] - ev / 3.0;
            const double d2 = s.eps[2][i] - ev / 3.0;
            volumetric[i] = ev;
            dev[0][i] = d0;
            dev[1][i] = d1;
            dev[2][i] = d2;
            norm[i] = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
        }
    }
    // |e|² of point i.
    double squaredNorm(int i) const
    {
        return dev[0][i] * dev[0][i] + dev[1][i] * dev[1][i] + dev[2][i] * dev[2][i];
    }
};

} // namespace sph
