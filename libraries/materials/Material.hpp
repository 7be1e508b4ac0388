#pragma once
// Hyperelastic materials: strain energy Ψ(F) per unit initial volume and the first
// Piola-Kirchhoff stress P = ∂Ψ/∂F (spec §8), runtime-selectable per body in constant/bodies:
//
//   material { type neoHookean; mu 0.3571e6; kappa 1.67e6; rho 1000; }
//
// Keys common to every material:
//   rho | initial density ρ0 [kg/m^3] (in 1D: mass per unit length) | required
//
// 1D is a bar (uniaxial), 2D is plane strain, 3D is full. The time step uses waveSpeed(F):
// the largest longitudinal wave speed in the reference configuration at the current F.
//
// A material may keep a per-particle history (plastic strain, docs/theory/plasticity.md): it
// declares the fields in the registry it is given, evaluates every stress as a trial state
// from the particle's last committed history (HistoryOf says whose) and changes that history
// only in commit(), once per accepted time level. Elastic materials ignore all of this.

#include "core/Format.hpp"
#include "core/Registry.hpp"
#include "particles/ParticleFields.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/Types.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace sph
{

// Whose committed history each gradient F[i] of an evaluation uses: particle first + i (its
// own gradient), or one packed state per gradient (the samples of the gradient-of-F scheme
// around one particle each keep their own history, docs/theory/plasticity.md §P7): state i at
// states + i * stride, and, when next is not null, the state a commit would make of it at F[i]
// into next + i * stride and its dissipation per unit initial volume into dissipation[i].
// A third mode: trial states only (no plastic flow) from the committed history of one particle
// for all F[i] (the linearised evaluation of the gradient-of-F scheme, §P7).
// With next, `changed` (when not null) says per state: changed[i] = 0 where the commit would
// keep state i bit for bit (a point that does not flow), and next + i * stride is then not
// written; 1 where it may differ (next written).
// The committed states' layouts: packed one after another (samples: component c of state i at
// i * stride + c), or in rows (samplesInRows, 2D and 3D only: component c of state i at
// c * rowLength + i, rowLength a multiple of rowBlock — or rowBlock / 2 for at most that many
// states, which a material then reads in rowBlock / 2 lanes — and each row's entries past the
// last state the initial state's component), so that a material reads rowBlock states'
// component with one load. The next states are packed either way, nextStride apart.
struct HistoryOf
{
    std::size_t first = 0;
    const double* states = nullptr;
    double* next = nullptr;
    double* dissipation = nullptr;
    std::size_t stride = 0;
    bool trialAround = false;
    std::uint8_t* changed = nullptr;
    std::size_t componentStride = 1;
    std::size_t nextStride = 0;

    static constexpr std::size_t rowBlock = 16;
    // The row length for count states in rows: whole blocks, or half a block for at most half
    // of one (the material reads those in half as many lanes).
    static constexpr std::size_t rowLengthFor(std::size_t count)
    {
        return count <= rowBlock / 2 ? rowBlock / 2 : (count + rowBlock - 1) / rowBlock * rowBlock;
    }

    static HistoryOf particles(std::size_t first) { return {first}; }
    static HistoryOf trialOf(std::size_t particle)
    {
        HistoryOf h{particle};
        h.trialAround = true;
        return h;
    }
    static HistoryOf samples(const double* states, std::size_t stride, double* next = nullptr,
                             double* dissipation = nullptr, std::uint8_t* changed = nullptr)
    {
        return {0, states, next, dissipation, stride, false, changed, 1, stride};
    }
    // (packedSize: the numbers of a packed state, the next states' stride)
    static HistoryOf samplesInRows(const double* states, std::size_t rowLength,
                                   std::size_t packedSize, double* next = nullptr,
                                   double* dissipation = nullptr, std::uint8_t* changed = nullptr)
    {
        return {0, states, next, dissipation, 1, false, changed, rowLength, packedSize};
    }
    bool perSample() const { return states != nullptr; }
    bool inRows() const { return componentStride != 1; }
    // Where component c of committed state i is.
    std::size_t at(std::size_t i, std::size_t c) const { return i * stride + c * componentStride; }
    std::size_t particle(std::size_t i) const { return trialAround ? first : first + i; }
};

// The return map's correction at one F, linearised (§P7, evaluation 2): with P_tr the trial
// (elastic) stress from the committed state, dP = P − P_tr, A = ∂dP/∂F (row-major D²×D²,
// A(i*D+j, k*D+l) = ∂dP_ij/∂F_kl) and dW = W − W_tr. All zero where the point does not flow.
template <int D>
struct PlasticCorrection
{
    bool flowing = false;
    Mat<D> dP = Mat<D>::Zero();
    Eigen::Matrix<double, D * D, D * D> A = Eigen::Matrix<double, D * D, D * D>::Zero();
    double dW = 0.0;
};

template <int D>
class Material : public RegisteredModel
{
public:
    static constexpr const char* family = "material";
    static constexpr int dimension = D;
    struct Args
    {
        // Where a material with history declares its per-particle fields (null in tests that
        // build a material alone), and the particles of the body it serves.
        ParticleFields<D>* fields = nullptr;
        BodyRange particles;
        // The particles' F of the last force evaluation, from which a material with history
        // computes the state it displays (null in tests).
        const std::vector<Mat<D>>* F = nullptr;
        // Whether the scheme evaluates the material at the particles' own F and history
        // (Stabilisation::evaluatesParticles): if not, a plastic material keeps no memo of
        // the particles' returns (ReturnMemo, which only those evaluations fill).
        bool particleEvaluations = true;
    };

    virtual ~Material() = default;

    double density() const { return rho_; }
    // Ψ, P and c of a material point in its initial state (no history yet).
    virtual double energy(const Mat<D>& F) const = 0;
    virtual Mat<D> stress(const Mat<D>& F) const = 0;
    virtual double waveSpeed(const Mat<D>& F) const = 0;
    // P[i] = P(F[i]) and, when psi is not null, psi[i] = Ψ(F[i]), for i < n, each with the
    // committed history of history.particle(i) (for a material with history Ψ is the
    // incremental energy W of docs/theory/plasticity.md (P4.2), of which P is the derivative).
    virtual void evaluate(const Mat<D>* F, Mat<D>* P, double* psi, std::size_t n,
                          HistoryOf history) const = 0;
    // The largest wave speed of particles first .. first + n at their gradients F[0 .. n).
    virtual double maxWaveSpeed(const Mat<D>* F, std::size_t n, std::size_t first) const = 0;
    // The same as forces see it whose gradients are taken in a moved reference configuration
    // with gradients Fr (updated Lagrangian): the stretch that shortens the waves is the one
    // since the reference, f = F Fr⁻¹, not the total F (theory (P2.6)). By default the
    // total-F bound, which is never smaller.
    virtual double maxWaveSpeedSinceReference(const Mat<D>* F, const Mat<D>* Fr, std::size_t n,
                                              std::size_t first) const
    {
        (void)Fr;
        return maxWaveSpeed(F, n, first);
    }
    // Young's modulus (used by hourglass control, spec §12).
    virtual double youngsModulus() const = 0;

    // Materials with history: whether there is one, and the commit of particles first ..
    // first + n at their gradients F (the accepted level), returning the energy this commit
    // dissipates, Σ V0 ΔD. Called once per level, after the level was written.
    virtual bool hasHistory() const { return false; }
    // Whether evaluate() takes per-sample states in rows (HistoryOf::samplesInRows); a
    // material that does not say so is handed them packed, one after another.
    virtual bool readsStatesInRows() const { return false; }
    // The linearised correction of the return map at F from particle a's committed state.
    virtual PlasticCorrection<D> plasticCorrection(const Mat<D>& F, std::size_t a) const
    {
        (void)F;
        (void)a;
        return {};
    }
    // The committed state of particle a as historyComponents() numbers (HistoryOf::samples).
    virtual std::size_t historyComponents() const { return 0; }
    virtual void packHistory(std::size_t a, double* out) const
    {
        (void)a;
        (void)out;
    }
    // The packed state of a point never committed (what packHistory gives for a new particle).
    virtual void packInitialHistory(double* out) const { (void)out; }
    // A compact form of packed states, for stores of many (gradF's samples): compact() writes
    // compactHistoryComponents() numbers from which expandHistory() gives the packed state back
    // bit for bit, and returns false for a state it could not give back so. By default the
    // packed state itself.
    virtual std::size_t compactHistoryComponents() const { return historyComponents(); }
    virtual bool compactHistory(const double* packed, double* out) const
    {
        std::copy(packed, packed + historyComponents(), out);
        return true;
    }
    virtual void expandHistory(const double* compact, double* out) const
    {
        std::copy(compact, compact + historyComponents(), out);
    }
    // A packed state (packHistory's layout) re-expressed so that its elastic state be at the
    // gradient `to` is the one it had at `from` (docs/theory/gradF-plastic.md (G4.1)): what a
    // stress sample's state becomes when the reference it is measured from moves.
    virtual void rebaseHistory(double* state, const Mat<D>& from, const Mat<D>& to) const
    {
        (void)state;
        (void)from;
        (void)to;
    }
    // rebaseHistory() for count packed states `stride` apart, state j from from[j], all to
    // the same `to` (a particle's stress samples at a move).
    virtual void rebaseHistories(double* states, std::size_t stride, std::size_t count,
                                 const Mat<D>* from, const Mat<D>& to) const
    {
        for (std::size_t j = 0; j < count; ++j)
        {
            rebaseHistory(states + j * stride, from[j], to);
        }
    }
    // Whether a point with the packed state `packed` at the gradient F has opened: it is
    // beyond a tension cut-off of zero, so that it carries no stress and holds no energy (a
    // cohesionless granular point whose voids are open, docs/theory/plasticity.md (P9.5));
    // what gradF's openedSamples particle acts on (docs/theory/gradF-plastic.md §G22). By
    // default never.
    virtual bool opened(const double* packed, const Mat<D>& F) const
    {
        (void)packed;
        (void)F;
        return false;
    }
    // The same for particle a's own committed state (its be at `to` is the one it had at
    // `from`).
    virtual void rebaseParticleHistory(std::size_t a, const Mat<D>& from, const Mat<D>& to)
    {
        (void)a;
        (void)from;
        (void)to;
    }
    // The registry fields rebaseParticleHistory() changes (a distributed run refreshes its
    // ghosts' from their owners after a move).
    virtual std::vector<std::string> rebasedFields() const { return {}; }
    virtual double commit(const Mat<D>* F, const double* V0, std::size_t first, std::size_t n)
    {
        (void)F;
        (void)V0;
        (void)first;
        (void)n;
        return 0.0;
    }

    // An initial stress (a body at rest under gravity, a pre-stressed part): sets particle a's
    // committed state so that its Cauchy stress at F = I is sigma (3×3 always: in 2D plane
    // strain the zz component is the out-of-plane stress; in 1D only xx is used). Only a
    // material whose history holds its stress-free configuration can (the plastic ones: an
    // initial elastic strain in Cp⁻¹); a stress outside the yield surface is refused.
    enum class InitialStress
    {
        set,
        notSupported,
        outsideYieldSurface
    };
    virtual InitialStress startFromStress(std::size_t a, const Eigen::Matrix3d& sigma)
    {
        (void)a;
        (void)sigma;
        return InitialStress::notSupported;
    }
    // K0 = σ_horizontal/σ_vertical of the material at rest under its own weight with no
    // lateral strain: ν/(1 − ν) for an elastic solid; a frictional material gives its own
    // (Jaky's 1 − sin φ). NaN when the material has no such coefficient.
    virtual double atRestCoefficient() const { return std::numeric_limits<double>::quiet_NaN(); }

    static Schema commonSchema()
    {
        return Schema().add(Key::real("rho", "initial density rho0 [kg/m^3] (1D: mass per unit "
                                             "length [kg/m])")
                                .positive());
    }

protected:
    explicit Material(const Params& params) : rho_(params.real("rho")) {}
    // The summary shows the wave speed at F = I: "neoHookean(rho=1000, ..., c=46.3264 m/s)".
    std::vector<std::string> summaryExtras() const override
    {
        return {"c=" + formatNumber(waveSpeed(Mat<D>::Identity())) + " m/s"};
    }

private:
    double rho_;
};

// Implements the batch and bookkeeping methods of Material<D> for a model that provides the
// inline, non-virtual  Mat<D> stressOf(F), double energyOf(F), double waveSpeedOf(F), and
// optionally a faster  void stressBatch(const Mat<D>* F, Mat<D>* P, std::size_t n).
template <int D, class Derived>
class MaterialModel : public Material<D>
{
public:
    using Material<D>::Material;

    double energy(const Mat<D>& F) const final { return self().energyOf(F); }
    Mat<D> stress(const Mat<D>& F) const final { return self().stressOf(F); }
    void evaluate(const Mat<D>* F, Mat<D>* P, double* psi, std::size_t n, HistoryOf) const final
    {
        if constexpr (requires(const Derived& m) { m.stressBatch(F, P, n); })
        {
            self().stressBatch(F, P, n);
        }
        else
        {
            for (std::size_t i = 0; i < n; ++i)
            {
                P[i] = self().stressOf(F[i]);
            }
        }
        if (psi)
        {
            for (std::size_t i = 0; i < n; ++i)
            {
                psi[i] = self().energyOf(F[i]);
            }
        }
    }
    double waveSpeed(const Mat<D>& F) const final { return self().waveSpeedOf(F); }
    double maxWaveSpeed(const Mat<D>* F, std::size_t n, std::size_t) const final
    {
        double c = 0.0;
        for (std::size_t i = 0; i < n; ++i)
        {
            c = std::max(c, self().waveSpeedOf(F[i]));
        }
        return c;
    }

private:
    const Derived& self() const { return static_cast<const Derived&>(*this); }
};

// Smallest and largest eigenvalue of C = F^T F (the squared principal stretches).
template <int D>
std::pair<double, double> stretchSquaredRange(const Mat<D>& F)
{
    const Mat<D> C = F.transpose() * F;
    if constexpr (D == 1)
    {
        return {C(0, 0), C(0, 0)};
    }
    else if constexpr (D == 2)
    {
        const double half = 0.5 * (C(0, 0) + C(1, 1));
        const double det = C(0, 0) * C(1, 1) - C(0, 1) * C(1, 0);
        const double root = std::sqrt(std::max(0.0, half * half - det));
        return {half - root, half + root};
    }
    else
    {
        Eigen::SelfAdjointEigenSolver<Mat<3>> solver;
        solver.computeDirect(C, Eigen::EigenvaluesOnly);
        return {solver.eigenvalues()[0], solver.eigenvalues()[2]};
    }
}

} // namespace sph
