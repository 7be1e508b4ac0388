#pragma once
// The per-particle history of the plastic materials (docs/theory/plasticity.md §P1, §P7): the
// inverse plastic right Cauchy–Green tensor Cp⁻¹ (its in-plane block; in 2D its zz component
// too; in 1D exp(−2 εp)) and the equivalent plastic strain α, as restart fields of the
// particle registry, plus the display fields every plastic material shows. One set of field
// specs for all plastic materials: bodies of different plastic materials share the arrays, and
// restart files keep loading whichever material wrote them.
//
// Fields: restart:inversePlasticCauchyGreen, restart:inversePlasticCauchyGreenZZ (2D),
// restart:plasticFlowPressure, restart:equivalentPlasticStrain (the committed state),
// plasticStrain and yielding (display, derived by the material at the written level).

#include "materials/Material.hpp"

#include <algorithm>
#include <cstring>
#include <memory>

namespace sph
{

// The flow pressure of a state whose last commit did not flow (or of a model that keeps none):
// above any pressure a material can carry (finite: restart data must be).
inline constexpr double noFlowPressure = 1e300;

// One committed state, and the same as historyComponents() numbers (HistoryOf::samples):
// Cp⁻¹ (D×D, row-major), then Cp⁻¹_zz (2D), then the flow pressure, then α. The flow pressure
// is the mean stress at which the commit that wrote the state flowed (noFlowPressure if it did
// not): the start of the next step's trapezoid for the dissipation of a non-associative flow
// (docs/theory/plasticity.md (P9.7)); only `druckerPrager` with ψ ≠ φ sets it.
template <int D>
struct PlasticState
{
    Mat<D> inversePlastic = Mat<D>::Identity();
    double inversePlasticZZ = 1.0;
    double flowPressure = noFlowPressure;
    double alpha = 0.0;

    static constexpr std::size_t flowPressureAt = D * D + (D == 2 ? 1 : 0);
    static constexpr std::size_t packedSize = flowPressureAt + 2;
    void pack(double* out) const;
    static PlasticState unpack(const double* in);

    // The compact form of a packed state (Material::compactHistory): Cp⁻¹ is symmetric, so its
    // upper triangle row by row, then the rest as packed, the flow pressure only for a model
    // that keeps one (3D: 7 or 8 numbers, not 11). compact() says whether expand() gives the
    // state back bit for bit (its Cp⁻¹ is symmetric to the bit, as every update of it makes it:
    // ½ (C + Cᵀ); without the flow pressure, that it is noFlowPressure).
    static constexpr std::size_t compactSize(bool withFlowPressure)
    {
        return D * (D + 1) / 2 + (D == 2 ? 1 : 0) + (withFlowPressure ? 1 : 0) + 1;
    }
    static bool compact(const double* packed, double* out, bool withFlowPressure);
    static void expand(const double* compact, double* packed, bool withFlowPressure);
};

// What a return did at one point: its plastic multiplier (> 0: the point flows), the α it
// leads to, the step's dissipation per unit initial volume and the flow pressure to keep.
struct PlasticFlow
{
    double deltaGamma = 0.0;
    double alpha = 0.0;
    double dissipation = 0.0;
    double pressure = noFlowPressure; // the flow pressure the state to commit keeps
};

template <int D>
class PlasticHistory
{
public:
    static std::vector<FieldSpec> fields();
    static const FieldSpec& plasticStrainField();
    static const FieldSpec& yieldingField();

    // Declares the restart fields in args.fields (or owns them when the material is built
    // alone, as in tests: then points beyond args.particles.end read as virgin).
    explicit PlasticHistory(const typename Material<D>::Args& args);

    PlasticState<D> state(std::size_t a) const;
    void store(std::size_t a, const PlasticState<D>& s);
    // A commit that did not flow: the state is kept, its flow pressure is forgotten (P9.7).
    // (Points a material built alone was not sized for read as virgin, see state().)
    void forgetFlowPressure(std::size_t a)
    {
        if (a < flowPressure_->size())
        {
            (*flowPressure_)[a] = noFlowPressure;
        }
    }
    // The registry the fields live in (the run's, or this history's own).
    ParticleFields<D>& registry() const { return *registry_; }

private:
    std::unique_ptr<ParticleFields<D>> ownFields_;
    ParticleFields<D>* registry_ = nullptr;
    std::vector<Mat<D>>* inversePlastic_ = nullptr;
    std::vector<double>* inversePlasticZZ_ = nullptr; // 2D only
    std::vector<double>* flowPressure_ = nullptr;
    std::vector<double>* alpha_ = nullptr;
};

// Inline: read for every particle and every gradF sample of every force evaluation.
template <int D>
inline void PlasticState<D>::pack(double* out) const
{
    for (int i = 0; i < D * D; ++i)
    {
        out[i] = inversePlastic(i / D, i % D);
    }
    if constexpr (D == 2)
    {
        out[D * D] = inversePlasticZZ;
    }
    out[flowPressureAt] = flowPressure;
    out[packedSize - 1] = alpha;
}

template <int D>
inline PlasticState<D> PlasticState<D>::unpack(const double* in)
{
    PlasticState s;
    for (int i = 0; i < D * D; ++i)
    {
        s.inversePlastic(i / D, i % D) = in[i];
    }
    if constexpr (D == 2)
    {
        s.inversePlasticZZ = in[D * D];
    }
    s.flowPressure = in[flowPressureAt];
    s.alpha = in[packedSize - 1];
    return s;
}

template <int D>
inline bool PlasticState<D>::compact(const double* packed, double* out, bool withFlowPressure)
{
    bool symmetric = true;
    for (int i = 0; i < D; ++i)
    {
        for (int j = i; j < D; ++j)
        {
            *out++ = packed[i * D + j];
            symmetric = symmetric && std::memcmp(&packed[i * D + j], &packed[j * D + i], sizeof(double)) == 0;
        }
    }
    if (withFlowPressure)
    {
        std::copy(packed + D * D, packed + packedSize, out);
        return symmetric;
    }
    std::copy(packed + D * D, packed + flowPressureAt, out);
    out[flowPressureAt - D * D] = packed[packedSize - 1];
    return symmetric && packed[flowPressureAt] == noFlowPressure;
}

template <int D>
inline void PlasticState<D>::expand(const double* compact, double* packed, bool withFlowPressure)
{
    for (int i = 0; i < D; ++i)
    {
        for (int j = i; j < D; ++j)
        {
            packed[i * D + j] = *compact;
            packed[j * D + i] = *compact++;
        }
    }
    if (withFlowPressure)
    {
        std::copy(compact, compact + (packedSize - D * D), packed + D * D);
        return;
    }
    std::copy(compact, compact + (flowPressureAt - D * D), packed + D * D);
    packed[flowPressureAt] = noFlowPressure;
    packed[packedSize - 1] = compact[flowPressureAt - D * D];
}

template <int D>
inline PlasticState<D> PlasticHistory<D>::state(std::size_t a) const
{
    PlasticState<D> s;
    if (ownFields_ && a >= alpha_->size())
    {
        return s; // a material built alone (tests): points it was not sized for are virgin
    }
    s.inversePlastic = (*inversePlastic_)[a];
    if constexpr (D == 2)
    {
        s.inversePlasticZZ = (*inversePlasticZZ_)[a];
    }
    s.flowPressure = (*flowPressure_)[a];
    s.alpha = (*alpha_)[a];
    return s;
}

} // namespace sph
