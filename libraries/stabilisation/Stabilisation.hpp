#pragma once
// Internal-force schemes ("stabilisation" in system/sphSchemes), runtime-selectable:
//
//   stabilisation { type gradF; }        // the types: sphSolid -listTypes stabilisation
//
// Every scheme works with both formulations (total- and updated-Lagrangian, which differ only
// in the reference configuration it is given) and in 1D/2D/3D. Each has an energy and a force:
// the force is -∂Π/∂x of the scheme's discrete energy Π (spec §3, §4, §5.1, §6), except
// hourglass control, whose pair forces are not derived from an energy (spec §12).
//
// Forces are computed in gather form (each particle sums what acts on it), so the result does
// not depend on the number of threads.

#include "core/Registry.hpp"
#include "kernels/Kernel.hpp"
#include "materials/Material.hpp"
#include "particles/ReferenceConfiguration.hpp"

#include <string>
#include <vector>

namespace sph
{

// What a force evaluation reads.
template <int D>
struct ForceInput
{
    const std::vector<Vec<D>>& x;                      // current positions
    const std::vector<double>& V0;                     // initial volumes
    const std::vector<int>& body;                      // body of each particle
    const std::vector<BodyRange>& bodies;              // contiguous particle ranges
    const std::vector<const Material<D>*>& materials;  // by body
    const ReferenceConfiguration<D>& ref;
    // x is the reference configuration itself (bitwise; the reference was set from these
    // positions this step), so f = I and ∇f = 0 exactly and need not be computed.
    bool atReference = false;
};

// What a force evaluation writes.
template <int D>
struct ForceOutput
{
    std::vector<Vec<D>>& T; // internal force on each particle
    std::vector<Mat<D>>& F; // deformation gradient F = f F^r
    std::vector<Mat<D>>& P; // first Piola-Kirchhoff stress at F
};

// A force evaluation's energy and, if the state is unusable, the first bad particle.
struct ForceStatus
{
    double strainEnergy = 0.0; // Π, when asked for
    long badParticle = -1;     // first particle with det F <= 0 or a non-finite value
    double badValue = 0.0;     // its det F
    std::string badQuantity;   // "det F", "force", ...
    bool ok() const { return badParticle < 0; }
};

template <int D>
class Stabilisation : public RegisteredModel
{
public:
    static constexpr const char* family = "stabilisation";
    static constexpr int dimension = D;
    struct Args
    {
        const Kernel* kernel = nullptr;
    };

    virtual ~Stabilisation() = default;

    // Radius of the reference neighbour search (the kernel support unless the scheme needs more).
    virtual double searchRadius(const Kernel& kernel) const { return kernel.supportRadius(); }
    // Whether the reference configuration must carry K = ∂F^r/∂x^r (the gradient-of-F scheme).
    virtual bool carriesReferenceGradient() const { return false; }
    // Whether the scheme reads the kernel values W_ab of the reference pairs (the gradients
    // are always there); a scheme that does not, does not pay for storing them.
    virtual bool needsKernelValues() const { return false; }
    // Precomputes what depends only on the reference configuration; called after every rebuild.
    // Returns the first particle where that data is singular, or -1.
    virtual long prepare(const ReferenceConfiguration<D>& ref) = 0;

    // F = f F^r at positions x (for moving the reference configuration to x). Schemes that
    // carry K also return the new K = G f^{-1} (spec §6.5) in newK.
    virtual ForceStatus referenceUpdate(const std::vector<Vec<D>>& x,
                                        const ReferenceConfiguration<D>& ref,
                                        std::vector<Mat<D>>& F,
                                        std::vector<Tensor3<D>>* newK) const = 0;

    // Internal forces, F and P at the current positions; the energy Π when wantEnergy.
    virtual ForceStatus computeForces(const ForceInput<D>& in, ForceOutput<D>& out,
                                      bool wantEnergy) = 0;

    // Π at the current positions (the energy the force derives from).
    virtual double energy(const ForceInput<D>& in) = 0;
};

} // namespace sph
