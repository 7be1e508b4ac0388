// `monaghan`: the artificial viscosity of Monaghan & Gingold (1983), Monaghan (1992, ARAA 30,
// eqs. 4.1-4.2), in the form used for solids by Gray, Monaghan & Swift (2001). For particles
// a, b of the same body with x_ab = x_a - x_b, v_ab = v_a - v_b,
//
//   Π_ab = (-α c̄_ab μ_ab + β μ_ab²) / ρ̄_ab   if v_ab·x_ab < 0 (approaching), else 0,
//   μ_ab = h v_ab·x_ab / (|x_ab|² + 0.01 h²),
//   a_a -= Σ_b m_b Π_ab ∇_a W_ab,   ∇_a W_ab = W'(|x_ab|) x_ab / |x_ab|,
//
// with c̄, ρ̄ the pair means, h and W the run's kernel.
//   ρ_a = ρ0 / det F_a: the current density, from F^n of the force evaluation.
//   c_a = c0 of the body, the wave speed at F = I (Material::waveSpeed(I)): the constant sound
//         speed of Gray et al.; the current speed differs by O(strain), which only rescales α,
//         and a constant c costs no material call per pair.
//   v    = v^{n-1/2}, the velocity the leapfrog holds when the forces at x^n are computed: the
//         viscosity is then known before Δt_n is chosen, so the step bound below sees the μ of
//         the very forces it integrates, and a restart recomputes them from the state file. A
//         predicted v^n = v^{n-1/2} + ½Δt a^n would need the walls' forces, which need Δt_n;
//         the lag of ½Δt in the velocity of a damping term is first order in Δt in the
//         dissipation only (the conservative forces keep the leapfrog's second order).
//
// Neighbours: the pairs within the kernel support in the CURRENT configuration x^n, in both
// formulations (particles/VerletNeighbours.hpp: a cell search with a 10 % skin, reused while no particle
// moved half the skin). The reference configuration's lists would be those of x^n in UL only
// at the steps the reference moves, and in TL never once the body deforms (a compressed body
// would gain pairs the viscosity never sees). The gradient is the plain kernel gradient, not
// the scheme's corrected one: it is antisymmetric, so with Π_ab = Π_ba the pair forces
// m_a m_b Π_ab ∇_a W_ab are equal and opposite and linear momentum is conserved to round-off;
// they are central (along x_ab), so angular momentum is conserved too. The viscosity acts
// within each body only (between bodies the contact model acts).
//
// Dissipation: Σ_a m_a v_a·a_a = -½ Σ_ab m_a m_b Π_ab W'/|x_ab| (v_ab·x_ab) <= 0, since
// W' <= 0, Π_ab >= 0 and v_ab·x_ab < 0 where Π_ab ≠ 0: the force only takes kinetic energy.
// It vanishes for rigid translation (v_ab = 0), rigid rotation (v_ab·x_ab = (ω × x_ab)·x_ab = 0)
// and separating particles.
//
// Gather form: each particle sums its own pairs in list order, so the result does not depend
// on the number of threads.
//
// Time step (Monaghan 1992, §10): Δt <= C h / (c + 1.2 (α c + β max_ab |μ_ab|)); the solver's
// Δt = courant h / c_max becomes courant h / signalSpeed(c_max) with that denominator (c_max
// for c: the bound is conservative, c_max >= c0 for the usual materials).
//
// Keys:
//   alpha | α, the linear (bulk) term, >= 0        | 1
//   beta  | β, the quadratic (shock) term, >= 0    | 2
#include "artificialViscosity/ArtificialViscosity.hpp"
#include "particles/VerletNeighbours.hpp"
#include "particles/Parallel.hpp"

#include <algorithm>

namespace sph
{

template <int D>
class Monaghan : public ArtificialViscosity<D>
{
public:
    static std::string description()
    {
        return "Monaghan's artificial viscosity (Monaghan & Gingold 1983; Monaghan 1992 eqs. "
               "4.1-4.2): a pair pressure (-alpha c mu + beta mu^2)/rho between approaching "
               "particles of a body, in the current configuration; dissipative, conserves "
               "momentum, bounds the time step.";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::real("alpha", "Monaghan's alpha, the linear (bulk viscosity) term; "
                                    "typically 0.5-1, 0 switches it off")
                     .nonNegative()
                     .defaultValue("1"))
            .add(Key::real("beta", "Monaghan's beta, the quadratic (shock) term against "
                                   "interpenetration; typically 2 alpha, 0 switches it off")
                     .nonNegative()
                     .defaultValue("2"));
    }

    Monaghan(const Params& params, const typename ArtificialViscosity<D>::Args& args)
        : kernel_(*args.kernel), alpha_(params.real("alpha")), beta_(params.real("beta"))
    {
        for (const Material<D>* material : args.materials)
        {
            soundSpeed_.push_back(material->waveSpeed(Mat<D>::Identity()));
            density_.push_back(material->density());
        }
    }

    bool active() const override { return true; }
    double reach() const override { return kernel_.supportRadius(); }
    void particlesChanged() override { neighbours_.clear(); }

    void compute(const ViscosityState<D>& state, std::vector<Vec<D>>& acceleration) override
    {
        const ParticleSet<D>& p = state.particles;
        const std::size_t n = p.size();
        acceleration.assign(n, Vec<D>::Zero());
        const NeighbourList& list = neighbours_.update(state.x, p.body, kernel_.supportRadius());
        rho_.resize(n);
        c_.resize(n);
#pragma omp parallel for schedule(static) if (useThreads(n))
        for (std::size_t a = 0; a < n; ++a)
        {
            const auto body = static_cast<std::size_t>(p.body[a]);
            rho_[a] = density_[body] / p.F[a].determinant();
            c_[a] = soundSpeed_[body];
        }
        const double h = kernel_.h();
        const double eps = 0.01 * h * h;
        double muMax = 0.0;
#pragma omp parallel for schedule(static) reduction(max : muMax) if (useThreads(n))
        for (std::size_t a = 0; a < n; ++a)
        {
            if (p.fixed[a] || (state.ranks && !state.ranks->counts(a)))
            {
                continue; // a ghost: its owner computes it
            }
            Vec<D> sum = Vec<D>::Zero();
            for (std::size_t k = list.begin(a) + 1; k < list.end(a); ++k) // self first: skipped
            {
                const std::size_t b = list.indices[k];
                const Vec<D> xab = state.x[a] - state.x[b];
                const double approach = (state.v[a] - state.v[b]).dot(xab);
                if (!(approach < 0.0))
                {
                    continue;
                }
                const double r2 = xab.squaredNorm();
                const double r = std::sqrt(r2);
                const double mu = h * approach / (r2 + eps);
                const double pi = (-alpha_ * 0.5 * (c_[a] + c_[b]) * mu + beta_ * mu * mu) /
                                  (0.5 * (rho_[a] + rho_[b]));
                sum += (p.m[b] * pi * kernel_.dWdr(r) / r) * xab;
                muMax = std::max(muMax, -mu);
            }
            acceleration[a] = -sum;
        }
        if (state.ranks)
        {
            std::vector<double> largest{muMax};
            state.ranks->maximum(largest); // every rank bounds the step alike
            muMax = largest[0];
        }
        muMax_ = muMax;
    }

    double signalSpeed(double c) const override
    {
        return c + 1.2 * (alpha_ * c + beta_ * muMax_);
    }

private:
    const Kernel& kernel_;
    double alpha_;
    double beta_;
    std::vector<double> soundSpeed_; // by body: c0
    std::vector<double> density_;    // by body: ρ0
    VerletNeighbours<D> neighbours_;
    std::vector<double> rho_; // per particle, this level
    std::vector<double> c_;
    double muMax_ = 0.0; // max |μ_ab| of the last compute
};

SPH_REGISTER_DIM_MODEL(ArtificialViscosity, Monaghan, "monaghan");

} // namespace sph
