#include "stabilisation/oneSided/OneSided.hpp"

#include "core/InputError.hpp"
#include "particles/ParticleFields.hpp"

namespace sph
{

namespace
{

const char* const sideNames[6] = {"px", "mx", "py", "my", "pz", "mz"};

} // namespace

template <int D>
std::string OneSided<D>::description()
{
    return "sphSolid's own extension (not Vidal's scheme): the energy averaged over the 2D "
           "one-sided corrected gradients of each particle (neighbours on the +x side, the -x "
           "side, ...), force its exact derivative; no parameter. Sees the 2D sawtooths and the "
           "checkerboard that no shift of the gradient (vidal) can (docs/theory/vidal-modes.md "
           "§V7). Elastic materials only; costs 2D material evaluations per particle. Rings map "
           "(tutorials/rings2D/vidalStabilityMap): stable in 12 of 12 runs (vidal 4 of 84); fails the "
           "zeroEnergyMode and tensileInstability hard cases (docs/results.md §1.1).";
}

template <int D>
Schema OneSided<D>::schema()
{
    return Schema();
}

template <int D>
OneSided<D>::OneSided(const Params& params, const typename Stabilisation<D>::Args& args)
    : kernel_(*args.kernel), where_(params.source().location())
{
    for (int j = 0; j < sides; ++j)
    {
        if (args.fields)
        {
            G_[j] = &args.fields->template declare<Mat<D>>(
                FieldSpec::tensor(std::string("oneSidedCarried_") + sideNames[j],
                                  "oneSided: side " + std::string(sideNames[j]) +
                                      "'s deformation carried across reference moves, "
                                      "F^j = f^j G^j F^r")
                    .restart(),
                Mat<D>::Identity());
        }
        else
        {
            G_[j] = &ownG_[j];
        }
    }
}

template <int D>
double OneSided<D>::sideWeight(int j, const Vec<D>& fromAtoB, double tolerance)
{
    const double along = (j % 2 == 0 ? 1.0 : -1.0) * fromAtoB[j / 2];
    return along > tolerance ? 1.0 : (along < -tolerance ? 0.0 : 0.5);
}

template <int D>
void OneSided<D>::declareHistory(const std::vector<const Material<D>*>& materials,
                                  ParticleFields<D>&)
{
    for (const Material<D>* material : materials)
    {
        if (material && material->hasHistory())
        {
            throw InputError(where_,
                             "oneSided: a material with history (plasticity) is not supported",
                             {"oneSided evaluates each particle's material once per side (2D "
                              "times) and would need a history per side.",
                              "Valid with it: stabilisation gradF, none, vidal, hourglass; or an "
                              "elastic material with oneSided."});
        }
    }
}

template <int D>
ForceStatus OneSided<D>::prepare(const ReferenceConfiguration<D>& ref)
{
    const NeighbourList& list = ref.neighbours;
    const std::size_t n = ref.size();
    const double tolerance = 1.0e-9 * kernel_.h();
    for (int j = 0; j < sides; ++j)
    {
        if (pending_ && pendingG_[j].size() == n)
        {
            *G_[j] = pendingG_[j]; // the reference has moved (moveHistory())
        }
        resizePairArray(out_[j], list.pairCount());
        resizePairArray(in_[j], list.pairCount());
        if (G_[j]->size() != n)
        {
            G_[j]->resize(n, Mat<D>::Identity());
        }
    }
    pending_ = false;
    const StandardGradients<D> standard{ref};
    resizePairArray(grad_, list.pairCount());
#pragma omp parallel for schedule(static) if (useThreads(n))
    for (std::size_t a = 0; a < n; ++a)
    {
        const auto pairs = standard.particle(a);
        for (std::size_t k = list.begin(a); k < list.end(a); ++k)
        {
            grad_[k] = list.indices[k] == a ? Vec<D>::Zero() : pairs.outgoing(k); // ∇W(x^r_a - x^r_b)
        }
    }
    // A side whose own neighbours do not span every direction well (σ_min(M^j_a) below
    // fullBelow; 0.5 inside a lattice, 0 on the outer side of a free surface) uses a's whole
    // support instead: f^j_a = f_a there, the plain corrected gradient.
    for (int j = 0; j < sides; ++j)
    {
        whole_[j].assign(n, 0);
    }
#pragma omp parallel for schedule(static) if (useThreads(n))
    for (std::size_t a = 0; a < n; ++a)
    {
        for (int j = 0; j < sides; ++j)
        {
            Mat<D> M = Mat<D>::Zero();
            for (std::size_t k = list.begin(a) + 1; k < list.end(a); ++k)
            {
                const std::size_t b = list.indices[k];
                const Vec<D> ab = ref.x[b] - ref.x[a];
                M.noalias() += (ref.V[b] * sideWeight(j, ab, tolerance)) * ab * grad_[k].transpose();
            }
            const Eigen::JacobiSVD<Mat<D>> svd(M);
            const double smallest = M.allFinite() ? svd.singularValues()[D - 1] : 0.0;
            whole_[j][a] = smallest < fullBelow ? 1 : 0;
        }
    }
#pragma omp parallel for schedule(static) if (useThreads(n))
    for (std::size_t a = 0; a < n; ++a)
    {
        for (std::size_t k = list.begin(a); k < list.end(a); ++k)
        {
            const std::size_t b = list.indices[k];
            const Vec<D> ab = ref.x[b] - ref.x[a];
            for (int j = 0; j < sides; ++j)
            {
                out_[j][k] = (whole_[j][a] ? 1.0 : sideWeight(j, ab, tolerance)) * grad_[k];
                // b's side-j operator weighs a by the sign of x^r_a - x^r_b along e_i (or takes
                // its whole support), and uses ∇W(x^r_b - x^r_a) = -∇W(x^r_a - x^r_b).
                in_[j][k] = -(whole_[j][b] ? 1.0 : sideWeight(j, Vec<D>(-ab), tolerance)) * grad_[k];
            }
        }
    }
    for (int j = 0; j < sides; ++j)
    {
        // A particle whose whole support is singular is the reference's own failure (the
        // standard M, reported by the reference); here it is regularised as CorrectedGradient
        // does.
        (void)corrected_[j].build(list, ref.x, ref.V,
                                  [this, j](std::size_t) {
                                      return [this, j](std::size_t k) { return out_[j][k]; };
                                  },
                                  ref.owned);
    }
    return {};
}

template <int D>
const Mat<D>& OneSided<D>::carried(int j, std::size_t a) const
{
    static const Mat<D> identity = Mat<D>::Identity();
    const std::vector<Mat<D>>& G = *G_[j];
    return a < G.size() ? G[a] : identity;
}

template <int D>
Mat<D> OneSided<D>::sideDeformationGradient(int j, std::size_t a, const std::vector<Vec<D>>& x,
                                             const ReferenceConfiguration<D>& ref) const
{
    return incrementalGradient<D>(a, x, ref, gradients(j)) * carried(j, a) * ref.F[a];
}

template <int D>
Mat<D> OneSided<D>::deformationGradient(std::size_t a, const std::vector<Vec<D>>& x,
                                         const ReferenceConfiguration<D>& ref) const
{
    Mat<D> sum = Mat<D>::Zero();
    for (int j = 0; j < sides; ++j)
    {
        sum += sideDeformationGradient(j, a, x, ref);
    }
    return sum / sides;
}

template <int D>
ForceStatus OneSided<D>::referenceUpdate(const std::vector<Vec<D>>& x,
                                          const ReferenceConfiguration<D>& ref,
                                          std::vector<Mat<D>>& F, std::vector<Tensor3<D>>*) const
{
    const std::size_t n = ref.size();
    F.resize(n);
    long bad = -1;
    double badJ = 0.0;
    for (std::size_t a = 0; a < n; ++a)
    {
        const Mat<D> mean = deformationGradient(a, x, ref); // reads ref.F[a] before F[a] is set
        double J;
        if (!admissible<D>(mean, J) && bad < 0 && ref.counts(a))
        {
            bad = static_cast<long>(a);
            badJ = J;
        }
        F[a] = mean;
    }
    return bad < 0 ? ForceStatus{}
                   : ForceStatus::failed(FailureKind::nonPositiveJacobian, bad, badJ, "det F");
}

template <int D>
void OneSided<D>::moveHistory(const std::vector<Vec<D>>& x, const ReferenceConfiguration<D>& ref,
                               const std::vector<int>&, const std::vector<Material<D>*>&)
{
    const std::size_t n = ref.size();
    for (int j = 0; j < sides; ++j)
    {
        pendingG_[j].assign(n, Mat<D>::Identity());
    }
    for (std::size_t a = 0; a < n; ++a)
    {
        std::array<Mat<D>, sides> Fj;
        Mat<D> mean = Mat<D>::Zero();
        for (int j = 0; j < sides; ++j)
        {
            Fj[j] = sideDeformationGradient(j, a, x, ref);
            mean += Fj[j];
        }
        mean /= sides;
        double J;
        if (!admissible<D>(mean, J))
        {
            continue; // the move fails there and the run stops
        }
        // F^j = f^j G^j F^r stays what it is once F^r is the mean: G^j_new = F^j mean^{-1}.
        const Mat<D> inverse = mean.inverse();
        for (int j = 0; j < sides; ++j)
        {
            pendingG_[j][a] = Fj[j] * inverse;
        }
    }
    pending_ = true;
}

template <int D>
ForceStatus OneSided<D>::computeForces(const ForceInput<D>& in, ForceOutput<D>& out,
                                        bool wantEnergy)
{
    const std::size_t n = in.ref.size();
    out.T.assign(n, Vec<D>::Zero());
    out.F.assign(n, Mat<D>::Zero());
    out.P.assign(n, Mat<D>::Zero());
    ChunkTally tally;
    for (int j = 0; j < sides; ++j)
    {
        const StoredGradients<D> g = gradients(j);
        F_[j].resize(n);
        P_[j].resize(n);
        UL_[j].resize(n);
        psi_[j].resize(n);
#pragma omp parallel for schedule(static) if (useThreads(n))
        for (std::size_t a = 0; a < n; ++a)
        {
            const Mat<D> f = in.atReference ? Mat<D>::Identity()
                                            : incrementalGradient<D>(a, in.x, in.ref, g);
            F_[j][a] = f * carried(j, a) * in.ref.F[a];
        }
        for (std::size_t a = 0; a < n; ++a)
        {
            double J;
            if (!admissible<D>(F_[j][a], J))
            {
                if (in.counts(a))
                {
                    tally.flagJacobian(a, J);
                }
                F_[j][a].setIdentity(); // keep the arithmetic finite; the run stops
            }
        }
        for (std::size_t b = 0; b < in.bodies.size(); ++b)
        {
            const BodyRange& range = in.bodies[b];
            if (range.end > range.begin)
            {
                in.materials[b]->evaluate(&F_[j][range.begin], &P_[j][range.begin],
                                          wantEnergy ? &psi_[j][range.begin] : nullptr,
                                          range.end - range.begin,
                                          HistoryOf::particles(range.begin));
            }
        }
        for (std::size_t a = 0; a < n; ++a)
        {
            // U^j_a L^j_a with U^j_a = V0_a P^j_a (G^j_a F^r_a)^T: ∂F^j_a/∂x = g^j ⊗ G^j F^r.
            UL_[j][a] = in.V0[a] * P_[j][a] * (carried(j, a) * in.ref.F[a]).transpose() *
                        g.L(a);
            out.F[a] += F_[j][a] / sides;
            out.P[a] += P_[j][a] / sides;
            if (wantEnergy && in.counts(a))
            {
                tally.energy += in.V0[a] * psi_[j][a] / sides;
            }
        }
#pragma omp parallel for schedule(static) if (useThreads(n))
        for (std::size_t c = 0; c < n; ++c)
        {
            out.T[c] += gatherCsphForce<D>(c, in.ref, g, UL_[j]) / sides;
        }
    }
    ForceStatus status = combine({tally});
    checkForces<D>(out.T, status, in.owned);
    return status;
}

template <int D>
double OneSided<D>::energy(const ForceInput<D>& in)
{
    double total = 0.0;
    for (std::size_t b = 0; b < in.bodies.size(); ++b)
    {
        const BodyRange& range = in.bodies[b];
        const Material<D>& material = *in.materials[b];
        for (std::size_t a = range.begin; a < range.end; ++a)
        {
            if (!in.counts(a))
            {
                continue; // a ghost: its owner counts it
            }
            for (int j = 0; j < sides; ++j)
            {
                const Mat<D> F = sideDeformationGradient(j, a, in.x, in.ref);
                Mat<D> P;
                double psi;
                material.evaluate(&F, &P, &psi, 1, HistoryOf::particles(a));
                total += in.V0[a] * psi / sides;
            }
        }
    }
    return total;
}

template class OneSided<1>;
template class OneSided<2>;
template class OneSided<3>;

SPH_REGISTER_DIM_MODEL(Stabilisation, OneSided, "oneSided");

} // namespace sph
