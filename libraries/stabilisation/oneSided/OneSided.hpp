#pragma once
// `oneSided`: sphSolid's own stabilisation (issue 34 item 3; docs/theory/vidal-modes.md §V7).
// Not Vidal et al.'s scheme, nor a reading of it: an extension this project derived after
// showing that no shifted gradient (the `vidal` reconstruction) can see the 2D checkerboard.
//
// For each of the 2D directions s e_i (i = 1..D, s = ±1) particle a has a one-sided corrected
// gradient, built as in spec §2 from the half of its neighbours on that side:
//   d^j_ab = w^j_ab ∇W(x^r_a − x^r_b),  w^j_ab = 1 if s (x^r_b − x^r_a)_i > 0, ½ if = 0, 0 if < 0,
//   M^j_a = Σ_b V_b x^r_ba ⊗ d^j_ab,  L^j_a = (M^j_a)^{-T},  f^j_a = [Σ_b V_b x_ba ⊗ d^j_ab] (M^j_a)^{-1},
// each exact for affine maps. A side whose neighbours do not span every direction well
// (σ_min(M^j_a) < 0.1, against 0.5 inside a lattice: the outer side at a free surface) takes
// the whole support instead (f^j_a = f_a, plain CSPH there). The energy averages the sides,
//   Π = Σ_a V0_a (1/2D) Σ_j Ψ(F^j_a),   F^j_a = f^j_a G^j_a F^r_a,
// and the force is its exact derivative: T_c = (1/2D) Σ_j T^j_c, each T^j the CSPH force of
// side j. Averaging the gradients instead (one F from Σ_j d^j = d) would be plain CSPH: the
// modes' responses of opposite sides are opposite (§V7) and cancel in a sum, not in Ψ's average.
// G^j_a carries side j's own deformation across moves of the reference (updated Lagrangian):
// when the reference moves, F^r_a becomes the mean of the F^j_a and G^j_a = F^j_a (F^r_a)^{-1},
// so each side keeps what it saw (G = I in total-Lagrangian form). The new G is worked out in
// moveHistory() (the old reference still in place) and takes over in the prepare() that follows
// the move, so referenceUpdate() stays a pure function of its arguments. The F and P written out are
// the means over the sides. No parameter. Materials with history are refused (each side would
// need its own history).

#include "stabilisation/CsphOperators.hpp"

#include <array>

namespace sph
{

template <int D>
class OneSided : public Stabilisation<D>
{
public:
    static constexpr int sides = 2 * D;
    // A side whose M^j_a has a singular value below this uses the whole support (M^j = I/2 on
    // a lattice, M = I).
    static constexpr double fullBelow = 0.1;

    static std::string description();
    static Schema schema();
    OneSided(const Params& params, const typename Stabilisation<D>::Args& args);

    // The side-j weight of the pair a -> b: 1, ½ or 0 (j = 2i for +e_i, 2i + 1 for −e_i).
    static double sideWeight(int j, const Vec<D>& fromAtoB, double tolerance);

    ForceStatus prepare(const ReferenceConfiguration<D>& ref) override;
    ForceStatus referenceUpdate(const std::vector<Vec<D>>& x, const ReferenceConfiguration<D>& ref,
                                std::vector<Mat<D>>& F, std::vector<Tensor3<D>>*) const override;
    Mat<D> deformationGradient(std::size_t a, const std::vector<Vec<D>>& x,
                               const ReferenceConfiguration<D>& ref) const override;
    ForceStatus computeForces(const ForceInput<D>& in, ForceOutput<D>& out,
                              bool wantEnergy) override;
    double energy(const ForceInput<D>& in) override;
    void declareHistory(const std::vector<const Material<D>*>& materials,
                        ParticleFields<D>& fields) override;
    void moveHistory(const std::vector<Vec<D>>& x, const ReferenceConfiguration<D>& ref,
                     const std::vector<int>& body,
                     const std::vector<Material<D>*>& materials) override;

    // Side j's F^j_a = f^j_a G^j_a F^r_a at positions x (public for the mode test).
    Mat<D> sideDeformationGradient(int j, std::size_t a, const std::vector<Vec<D>>& x,
                                   const ReferenceConfiguration<D>& ref) const;

private:
    StoredGradients<D> gradients(int j) const { return {out_[j], in_[j], corrected_[j]}; }
    const Mat<D>& carried(int j, std::size_t a) const;

    const Kernel& kernel_;
    SourceLocation where_;
    std::vector<Vec<D>> grad_; // ∇W(x^r_a - x^r_b) per pair slot
    std::array<std::vector<std::uint8_t>, sides> whole_; // side j of a uses a's whole support
    std::array<std::vector<Vec<D>>, sides> out_;
    std::array<std::vector<Vec<D>>, sides> in_;
    std::array<CorrectedGradient<D>, sides> corrected_;
    // G^j per particle: particle fields (restart data, moved with the particles) when the
    // solver gives a registry, else owned here (unit tests).
    std::array<std::vector<Mat<D>>*, sides> G_{};
    std::array<std::vector<Mat<D>>, sides> ownG_;
    std::array<std::vector<Mat<D>>, sides> pendingG_; // from moveHistory(), for the next prepare()
    bool pending_ = false;
    // Per side: F^j, P^j, ψ^j, U^j L^j of the last evaluation.
    std::array<std::vector<Mat<D>>, sides> F_, P_, UL_;
    std::array<std::vector<double>, sides> psi_;
};

} // namespace sph
