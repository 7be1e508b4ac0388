#pragma once
// ReturnMapPlasticity at one point: the return map of a single F (the bar's uniaxial law in 1D,
// §P6; in 2D and 3D the point in the first of the lanes, so that it gives the digits of every
// other path), the linearised correction of the plastic return by central differences (§P7,
// `plasticSamples linearised`), and the inverse of the elastic law for an initial stress
// (§P10). Included at the end of ReturnMapPlasticity.hpp, whose members it defines.

#include "materials/plasticity/ReturnMapLanes.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace sph
{

template <int D, class Model>
typename ReturnMapPlasticity<D, Model>::Result
ReturnMapPlasticity<D, Model>::returnMap(const Mat<D>& F, const State& committed, bool wantNext,
                                         bool flow) const
{
    Result r;
    if constexpr (D == 1)
    {
        // §P6: ε = ½ ln(λ² Cp⁻¹), then the model's uniaxial return.
        const double lambda = F(0, 0);
        const double E = elastic_.E;
        double eps = 0.5 * std::log(lambda * lambda * committed.inversePlastic(0, 0));
        if (flow)
        {
            r.flow = model().returnUniaxial(eps, committed.alpha);
        }
        const double tau = E * eps;
        r.P = Mat<D>::Constant(tau / lambda);
        r.waveModulus = E + std::abs(tau);
        r.energy = 0.5 * E * eps * eps;
        if (wantNext)
        {
            r.next.inversePlastic = Mat<D>::Constant(std::exp(2.0 * eps) / (lambda * lambda));
        }
    }
    else
    {
        // The point in the first of `lanes` lanes (the others idle): every return of a point
        // runs the same instructions on its lane, one point or sixteen, so a point gives the
        // same digits whichever path evaluates it (the memo and restarts rely on it). (A
        // one-lane instantiation would too (the library fuses multiply-adds only explicitly), but
        // one instantiation is one code to trust.)
        double packed[State::packedSize];
        committed.pack(packed);
        LanesResult<lanes> one;
        returnInLanes<lanes>(&F, packed, State::packedSize, 1, flow, {wantNext, true, true}, one);
        r.P = one.stressAt(0);
        r.energy = one.energy[0];
        r.flow = one.flowAt(0);
        r.waveModulus = one.waveModulus[0];
        if (wantNext && r.flow.deltaGamma > 0.0)
        {
            r.next = one.nextAt(0);
        }
        r.next.alpha = r.flow.alpha;
        return r;
    }
    if (!(r.flow.deltaGamma > 0.0))
    {
        r.flow.alpha = committed.alpha;
    }
    if (committed.alpha > 0.0 || r.flow.deltaGamma > 0.0)
    {
        // Without any plastic flow the energy stays Hencky's (to round-off).
        r.energy += model().extraEnergy(r.flow);
    }
    r.next.alpha = r.flow.alpha;
    return r;
}

template <int D, class Model>
PlasticCorrection<D> ReturnMapPlasticity<D, Model>::plasticCorrection(const Mat<D>& F,
                                                                      std::size_t a) const
{
    const State s = state(a);
    const auto correction = [&](const Mat<D>& at, double* dW)
    {
        const Result full = returnMap(at, s, false);
        const Result trial = returnMap(at, s, false, false);
        if (dW)
        {
            *dW = full.energy - trial.energy;
        }
        return Mat<D>(full.P - trial.P);
    };
    PlasticCorrection<D> c;
    if (!(returnMap(F, s, false).flow.deltaGamma > 0.0))
    {
        return c;
    }
    c.flowing = true;
    c.dP = correction(F, &c.dW);
    const double h = 1e-7 * std::max(1.0, F.norm());
    for (int k = 0; k < D; ++k)
    {
        for (int l = 0; l < D; ++l)
        {
            Mat<D> plus = F;
            Mat<D> minus = F;
            plus(k, l) += h;
            minus(k, l) -= h;
            const Mat<D> dPdF = (correction(plus, nullptr) - correction(minus, nullptr)) / (2 * h);
            for (int i = 0; i < D; ++i)
            {
                for (int j = 0; j < D; ++j)
                {
                    c.A(i * D + j, k * D + l) = dPdF(i, j);
                }
            }
        }
    }
    return c;
}

template <int D, class Model>
typename Material<D>::InitialStress
ReturnMapPlasticity<D, Model>::startFromStress(std::size_t a, const Eigen::Matrix3d& sigma)
{
    State s;
    if constexpr (D == 1)
    {
        s.inversePlastic(0, 0) = std::exp(2.0 * sigma(0, 0) / elastic_.E);
    }
    else
    {
        // Principal axes of the stress (in 2D: of its in-plane block; zz is one of them).
        const Mat<D> inPlane = sigma.template topLeftCorner<D, D>();
        const Eigen::SelfAdjointEigenSolver<Mat<D>> axes(inPlane);
        Eigen::Vector3d tau = Eigen::Vector3d::Constant(sigma(2, 2));
        tau.template head<D>() = axes.eigenvalues();
        const Eigen::Vector3d eps = law_.strainOf(tau);
        const Vec<D> stretch = (2.0 * eps.template head<D>()).array().exp();
        s.inversePlastic = axes.eigenvectors() * stretch.asDiagonal() * axes.eigenvectors().transpose();
        s.inversePlastic = 0.5 * (s.inversePlastic + s.inversePlastic.transpose());
        s.inversePlasticZZ = D == 2 ? std::exp(2.0 * eps[2]) : 1.0;
    }
    // Outside the yield surface (or beyond what the elastic law can hold, e.g. a tension
    // above druckerPrager's tensile strength): the point would not keep the stress.
    const Result atStart = returnMap(Mat<D>::Identity(), s, false);
    const Mat<D> given = sigma.template topLeftCorner<D, D>();
    if (atStart.flow.deltaGamma > 0.0 ||
        (atStart.P - given).cwiseAbs().maxCoeff() > 1e-9 * std::max(sigma.norm(), 1e-300))
    {
        return Material<D>::InitialStress::outsideYieldSurface;
    }
    history_.store(a, s);
    return Material<D>::InitialStress::set;
}

} // namespace sph
