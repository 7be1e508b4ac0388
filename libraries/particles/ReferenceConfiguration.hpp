#pragma once
// The reference configuration of CSPH (spec §3, §4): positions x^r, volumes V^r, the
// deformation gradient F^r from the initial configuration, and — for the gradient-of-F
// scheme — K = ∂F^r/∂x^r (spec §6.5); plus everything that depends only on them: neighbour
// lists, kernel values and gradients per pair, and the corrected gradient.
//
// Total-Lagrangian: x^r = X, V^r = V0, F^r = I, K = 0, built once.
// Updated-Lagrangian: x^r ← x, F^r ← F, V^r ← J V0 at each update, then rebuilt.

#include "kernels/Kernel.hpp"
#include "particles/CorrectedGradient.hpp"
#include "particles/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/VerletNeighbours.hpp"

#include <cstdint>
#include <vector>

namespace sph
{

template <int D>
struct ReferenceConfiguration
{
    std::vector<Vec<D>> x;     // x^r
    std::vector<double> V;     // V^r
    std::vector<Mat<D>> F;     // F^r
    std::vector<Tensor3<D>> K; // ∂F^r/∂x^r, only when the scheme carries it (else empty)

    NeighbourList neighbours;      // in x^r, same body, self first
    // Per pair W(|x^r_ab|), when the scheme needs it, and W'(r)/r, so that
    // ∇W_ab = W'(r)(x^r_a - x^r_b)/r = gradW(a, k): rebuilding the vector from x^r costs the
    // loops no more memory traffic than storing it, at half the size. Both empty when the
    // values are recomputed where they are used (recomputeKernelValues; read them through
    // kernelValues(a) then).
    std::vector<double> W;
    std::vector<double> dWdrOverR;
    // Not storing W and W'/r per pair (formulation key `kernelValues recomputed`): 16 B per
    // pair less (1.2 kB per particle in 3D), for a kernel evaluation per pair where a loop
    // reads them. The values are the stored ones, bit for bit.
    bool recomputeKernelValues = false;
    CorrectedGradient<D> gradient; // L_a, e_a from ∇W
    double searchRadius = 0.0;
    long updateStep = 0; // time step at which x^r was last set

    // Candidate pairs for moving references (see rebuild).
    VerletNeighbours<D> candidates;

    // A distributed run's owned particles (1) and ghosts (0): only owned particles count in the
    // checks of a reference move (a ghost cut at the edge of the ghost layer is its owner's to
    // check). Null: every particle counts.
    const std::vector<std::uint8_t>* owned = nullptr;
    bool counts(std::size_t a) const { return !owned || (*owned)[a] != 0; }

    std::size_t size() const { return x.size(); }

    // x^r = X, V^r = V0, F^r = I (and K = 0 when withGradient).
    void setInitial(const ParticleSet<D>& particles, bool withGradient);

    // Recomputes neighbour lists, kernel values and corrected gradients from x^r and V^r.
    // Returns the first particle whose corrected gradient is singular, or -1.
    // reuseCandidates: keep Verlet-style candidate lists (radius + 10 % skin) between calls and
    // only filter them while no particle has moved more than half the skin — for a reference
    // that moves often; the lists are the same as from a fresh search.
    // keepKernelValues: store W per pair (else W stays empty).
    long rebuild(const Kernel& kernel, const std::vector<int>& body, double radius,
                 bool reuseCandidates = false, bool keepKernelValues = true);

    // The kernel values of particle a's pairs: slot k of its list at [k - neighbours.begin(a)]
    // (W only when the scheme needs it). Stored: pointers into W and dWdrOverR. Recomputed:
    // evaluated by the code that would have stored them, into a buffer of the calling thread
    // that holds the last particle asked for (valid until the thread asks for another).
    struct PairKernelValues
    {
        const double* W = nullptr;
        const double* dWdrOverR = nullptr;
    };
    PairKernelValues kernelValues(std::size_t a) const
    {
        if (!recomputeKernelValues)
        {
            const std::size_t first = neighbours.begin(a);
            return {W.empty() ? nullptr : &W[first], &dWdrOverR[first]};
        }
        return recomputedKernelValues(a);
    }

    // ∇W_ab for slot k of a's list, with a's kernelValues(a).dWdrOverR (the loops over a's
    // pairs fetch them once).
    Vec<D> gradW(std::size_t a, std::size_t k, const double* dWdrOverRofA) const
    {
        return dWdrOverRofA[k - neighbours.begin(a)] * (x[a] - x[neighbours.indices[k]]);
    }
    Vec<D> gradW(std::size_t a, std::size_t k) const
    {
        return gradW(a, k, kernelValues(a).dWdrOverR);
    }
    // g_a(b) for slot k of a's list (k > begin(a)): V_b L_a ∇W_ab.
    Vec<D> g(std::size_t a, std::size_t k) const
    {
        return V[neighbours.indices[k]] * (gradient.L[a] * gradW(a, k));
    }
    // g_a(a) = L_a e_a
    Vec<D> gSelf(std::size_t a) const { return gradient.L[a] * gradient.e[a]; }

private:
    // r, W(r) and W'(r)/r of particle a's pairs into the vectors of `values` (the one
    // evaluation both the stored and the recomputed values come from).
    struct PairBuffers
    {
        std::vector<double> r;
        std::vector<double> w;
        std::vector<double> dwr;
    };
    void evaluatePairs(std::size_t a, PairBuffers& values) const;
    void storeKernelValues(bool withW);
    PairKernelValues recomputedKernelValues(std::size_t a) const;

    const Kernel* kernel_ = nullptr; // of the last rebuild
    bool keepsW_ = true;
    std::uint64_t version_ = 0; // a number no other rebuild of any reference had
};

} // namespace sph
