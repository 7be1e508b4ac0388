#include "materials/j2Plasticity/J2Plasticity.hpp"

#include "core/Format.hpp"

namespace sph
{

namespace
{

const FieldSpec& inversePlasticField()
{
    static const FieldSpec spec =
        FieldSpec::tensor("inversePlasticCauchyGreen",
                          "Cp^-1 = Fp^-1 Fp^-T of the last committed level (in-plane block)")
            .restart()
            .padding(TensorPadding::identity);
    return spec;
}
const FieldSpec& inversePlasticZZField()
{
    static const FieldSpec spec =
        FieldSpec::scalar("inversePlasticCauchyGreenZZ",
                          "zz component of Cp^-1 of the last committed level (2D plane strain)")
            .restart();
    return spec;
}
const FieldSpec& committedAlphaField()
{
    static const FieldSpec spec =
        FieldSpec::scalar("equivalentPlasticStrain",
                          "equivalent plastic strain alpha of the last committed level")
            .restart();
    return spec;
}
const FieldSpec& plasticStrainField()
{
    static const FieldSpec spec =
        FieldSpec::scalar("plasticStrain", "equivalent plastic strain alpha at this level")
            .display();
    return spec;
}
const FieldSpec& yieldingField()
{
    static const FieldSpec spec =
        FieldSpec::integer("yielding", "1 where the particle flows plastically at this level")
            .display();
    return spec;
}

} // namespace

template <int D>
std::string J2Plasticity<D>::description()
{
    return "Finite-strain von Mises plasticity, linear isotropic hardening: F = Fe Fp, Hencky "
           "elasticity, radial return in principal log strains (docs/theory/plasticity.md); 2D "
           "plane strain, 1D uniaxial stress.";
}

template <int D>
Schema J2Plasticity<D>::schema()
{
    return Material<D>::commonSchema()
        .include(IsotropicElasticity::schema())
        .add(Key::real("yieldStress", "initial yield stress sigmaY0 [Pa]").positive())
        .add(Key::real("hardeningModulus", "linear isotropic hardening modulus H = "
                                           "dsigmaY/dalpha [Pa]; > -3 mu (1D: > -E), < 0 "
                                           "softens")
                 .defaultValue("0"));
}

template <int D>
std::vector<FieldSpec> J2Plasticity<D>::fields()
{
    std::vector<FieldSpec> specs{inversePlasticField()};
    if constexpr (D == 2)
    {
        specs.push_back(inversePlasticZZField());
    }
    specs.push_back(committedAlphaField());
    specs.push_back(plasticStrainField());
    specs.push_back(yieldingField());
    return specs;
}

template <int D>
J2Plasticity<D>::J2Plasticity(const Params& params, const typename Material<D>::Args& args)
    : Material<D>(params), elastic_(IsotropicElasticity::read<D>(params)), law_(elastic_),
      sigmaY0_(params.real("yieldStress")), H_(params.real("hardeningModulus"))
{
    // Δγ > 0 needs a positive denominator in the return (§P5, §P6).
    const double limit = D == 1 ? -elastic_.E : -3.0 * elastic_.mu;
    if (!(H_ > limit))
    {
        params.fail("hardeningModulus",
                    "j2Plasticity: hardeningModulus " + formatNumber(H_) + " is below the limit " +
                        formatNumber(limit) + (D == 1 ? " (-E)" : " (-3 mu)") +
                        ": the return map has no solution (softening faster than elastic "
                        "unloading)",
                    {"Use a value in (" + formatNumber(limit) + ", inf); 0 is perfectly plastic."});
    }
    ParticleFields<D>* fields = args.fields;
    if (!fields)
    {
        ownFields_ = std::make_unique<ParticleFields<D>>();
        ownFields_->setSize(args.particles.end);
        fields = ownFields_.get();
    }
    inversePlastic_ = &fields->template declare<Mat<D>>(inversePlasticField(), Mat<D>::Identity());
    if constexpr (D == 2)
    {
        inversePlasticZZ_ = &fields->template declare<double>(inversePlasticZZField(), 1.0);
    }
    alpha_ = &fields->template declare<double>(committedAlphaField(), 0.0);
    if (args.F && args.fields)
    {
        const std::vector<Mat<D>>* F = args.F;
        fields->template deriveOver<double>(
            plasticStrainField(), args.particles.begin, args.particles.end,
            [this, F](std::size_t a) { return state(a).alpha + returnMap((*F)[a], state(a), false).deltaGamma; });
        fields->template deriveOver<int>(
            yieldingField(), args.particles.begin, args.particles.end,
            [this, F](std::size_t a) { return returnMap((*F)[a], state(a), false).deltaGamma > 0.0 ? 1 : 0; });
    }
}

template <int D>
typename J2Plasticity<D>::State J2Plasticity<D>::state(std::size_t a) const
{
    State s;
    if (ownFields_ && a >= alpha_->size())
    {
        return s; // a material built alone (tests): points it was not sized for are virgin
    }
    s.inversePlastic = (*inversePlastic_)[a];
    if constexpr (D == 2)
    {
        s.inversePlasticZZ = (*inversePlasticZZ_)[a];
    }
    s.alpha = (*alpha_)[a];
    return s;
}

template <int D>
double J2Plasticity<D>::hardeningEnergy(double alpha) const
{
    if (H_ >= 0.0 || sigmaY0_ + H_ * alpha >= 0.0)
    {
        return 0.5 * H_ * alpha * alpha;
    }
    const double exhausted = -sigmaY0_ / H_; // σy reaches 0 here and stays 0
    return 0.5 * H_ * exhausted * exhausted - sigmaY0_ * (alpha - exhausted);
}

template <int D>
double J2Plasticity<D>::radialReturn(Eigen::Vector3d& eps, double alpha) const
{
    const double ev = eps.sum();
    const Eigen::Vector3d dev = eps - Eigen::Vector3d::Constant(ev / 3.0);
    const double mu = elastic_.mu;
    const double qTrial = std::sqrt(1.5) * 2.0 * mu * dev.norm();
    if (!(qTrial > yieldStress(alpha)))
    {
        return 0.0;
    }
    double deltaGamma = (qTrial - sigmaY0_ - H_ * alpha) / (3.0 * mu + H_);
    if (sigmaY0_ + H_ * (alpha + deltaGamma) < 0.0)
    {
        deltaGamma = qTrial / (3.0 * mu); // softening exhausted: σy = 0, s = 0
    }
    eps = dev * (1.0 - 3.0 * mu * deltaGamma / qTrial) + Eigen::Vector3d::Constant(ev / 3.0);
    return deltaGamma;
}

template <int D>
typename J2Plasticity<D>::Result J2Plasticity<D>::returnMap(const Mat<D>& F, const State& committed,
                                                            bool wantNext, bool flow) const
{
    Result r;
    if constexpr (D == 1)
    {
        // §P6: ε = ½ ln(λ² Cp⁻¹) − Δγ sgn τ_tr.
        const double lambda = F(0, 0);
        const double E = elastic_.E;
        double eps = 0.5 * std::log(lambda * lambda * committed.inversePlastic(0, 0));
        const double tauTrial = E * eps;
        if (flow && std::abs(tauTrial) > yieldStress(committed.alpha))
        {
            r.deltaGamma = (std::abs(tauTrial) - sigmaY0_ - H_ * committed.alpha) / (E + H_);
            if (sigmaY0_ + H_ * (committed.alpha + r.deltaGamma) < 0.0)
            {
                r.deltaGamma = std::abs(tauTrial) / E;
            }
            eps -= std::copysign(r.deltaGamma, tauTrial);
        }
        const double tau = E * eps;
        r.P = Mat<D>::Constant(tau / lambda);
        r.maxAbsTau = std::abs(tau);
        r.energy = 0.5 * E * eps * eps;
        if (wantNext)
        {
            r.next.inversePlastic = Mat<D>::Constant(std::exp(2.0 * eps) / (lambda * lambda));
        }
    }
    else
    {
        PrincipalStrain<D> p =
            principalStrain<D>(F * committed.inversePlastic * F.transpose(), committed.inversePlasticZZ);
        r.deltaGamma = flow ? radialReturn(p.eps, committed.alpha) : 0.0;
        const Eigen::Vector3d tau = law_.kirchhoff(p.eps);
        const Mat<D> Finv = F.inverse();
        r.P = p.assemble(tau) * Finv.transpose();
        r.maxAbsTau = tau.cwiseAbs().maxCoeff();
        r.energy = law_.energy(p.eps);
        if (wantNext && r.deltaGamma > 0.0)
        {
            const Eigen::Vector3d be = (2.0 * p.eps).array().exp();
            const Mat<D> Cp = Finv * p.assemble(be) * Finv.transpose();
            r.next.inversePlastic = 0.5 * (Cp + Cp.transpose());
            r.next.inversePlasticZZ = D == 2 ? be[2] : 1.0;
        }
    }
    const double alpha = committed.alpha + r.deltaGamma;
    if (committed.alpha > 0.0 || r.deltaGamma > 0.0)
    {
        // Without any plastic flow the energy stays Hencky's to the bit.
        r.energy += hardeningEnergy(alpha) + sigmaY0_ * r.deltaGamma;
    }
    r.next.alpha = alpha;
    return r;
}

template <int D>
void J2Plasticity<D>::pack(const State& s, double* out)
{
    for (int i = 0; i < D * D; ++i)
    {
        out[i] = s.inversePlastic(i / D, i % D);
    }
    if constexpr (D == 2)
    {
        out[D * D] = s.inversePlasticZZ;
    }
    out[packedSize - 1] = s.alpha;
}

template <int D>
typename J2Plasticity<D>::State J2Plasticity<D>::unpack(const double* in)
{
    State s;
    for (int i = 0; i < D * D; ++i)
    {
        s.inversePlastic(i / D, i % D) = in[i];
    }
    if constexpr (D == 2)
    {
        s.inversePlasticZZ = in[D * D];
    }
    s.alpha = in[packedSize - 1];
    return s;
}

template <int D>
void J2Plasticity<D>::evaluate(const Mat<D>* F, Mat<D>* P, double* psi, std::size_t n,
                               HistoryOf history) const
{
    for (std::size_t i = 0; i < n; ++i)
    {
        if (!history.perSample())
        {
            const Result r = returnMap(F[i], state(history.particle(i)), false, !history.trialAround);
            P[i] = r.P;
            if (psi)
            {
                psi[i] = r.energy;
            }
            continue;
        }
        const double* committed = history.states + i * history.stride;
        const bool wantNext = history.next != nullptr;
        const Result r = returnMap(F[i], unpack(committed), wantNext);
        P[i] = r.P;
        if (psi)
        {
            psi[i] = r.energy;
        }
        if (wantNext)
        {
            double* next = history.next + i * history.stride;
            if (r.deltaGamma > 0.0)
            {
                pack(r.next, next);
            }
            else
            {
                std::copy(committed, committed + packedSize, next);
            }
            history.dissipation[i] = sigmaY0_ * r.deltaGamma;
        }
    }
}

template <int D>
PlasticCorrection<D> J2Plasticity<D>::plasticCorrection(const Mat<D>& F, std::size_t a) const
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
    if (!(returnMap(F, s, false).deltaGamma > 0.0))
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

template <int D>
double J2Plasticity<D>::waveSpeedOf(const Mat<D>& F, const State& s) const
{
    const Result r = returnMap(F, s, false);
    // (P2.5): the elastic modulus bounds the elastoplastic one; the total stretch sets the scale.
    const double M = D == 1 ? elastic_.E : law_.longitudinalModulus();
    const double lowest = stretchSquaredRange<D>(F).first;
    return std::sqrt((M + r.maxAbsTau) / lowest / this->density());
}

template <int D>
double J2Plasticity<D>::maxWaveSpeed(const Mat<D>* F, std::size_t n, std::size_t first) const
{
    double c = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
        c = std::max(c, waveSpeedOf(F[i], state(first + i)));
    }
    return c;
}

template <int D>
double J2Plasticity<D>::commit(const Mat<D>* F, const double* V0, std::size_t first, std::size_t n)
{
    double dissipated = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const std::size_t a = first + i;
        const Result r = returnMap(F[i], state(a), true);
        if (r.deltaGamma > 0.0)
        {
            (*inversePlastic_)[a] = r.next.inversePlastic;
            if constexpr (D == 2)
            {
                (*inversePlasticZZ_)[a] = r.next.inversePlasticZZ;
            }
            (*alpha_)[a] = r.next.alpha;
            dissipated += V0[i] * sigmaY0_ * r.deltaGamma;
        }
    }
    return dissipated;
}

template class J2Plasticity<1>;
template class J2Plasticity<2>;
template class J2Plasticity<3>;

SPH_REGISTER_DIM_MODEL(Material, J2Plasticity, "j2Plasticity");

} // namespace sph
