// The wave speed that sets the time step of materials with history (docs/theory/plasticity.md
// (P2.5), (P2.6)): from the total stretch in total-Lagrangian runs, from the stretch since the
// reference moved in updated-Lagrangian ones; elastic materials keep the total-F bound.
#include "numerics/NumericsSupport.hpp"

using namespace sph;

// (P2.5) and (P2.6): the total-F bound c² = (M + max|τ|)/(ρ0 λ_min(F)²) for forces in the
// initial configuration; the stretch since the reference, f = F Fr⁻¹, for forces in a moved
// one. f = I (the reference just moved) leaves (M + max|τ|)/ρ0, whatever the flow before; Fr = I
// is the total-F bound exactly.
TEST_CASE("plastic wave speed: the total stretch, or the stretch since the reference (P2.6)",
          "[plasticity][timeStep]")
{
    test::MaterialPoint<2> point("type j2Plasticity; E 2e9; nu 0.3; rho 2000; yieldStress 1e7;");
    Mat<2> F;
    F << 1.0, 6.0, 0.0, 1.0; // simple shear γ = 6: λ_min(F)² ≈ 0.027
    point.commit(F);
    const Mat<2> I = Mat<2>::Identity();
    const double total = point.material->maxWaveSpeed(&F, 1, 0);
    CHECK(point.material->maxWaveSpeedSinceReference(&F, &I, 1, 0) == total);
    const double moved = point.material->maxWaveSpeedSinceReference(&F, &F, 1, 0);
    // The same numerator M + max|τ| (the state is the same), the stretch 1 instead of λ_min(F).
    CHECK(moved == Approx(total * std::sqrt(stretchSquaredRange<2>(F).first)).epsilon(1e-12));
    CHECK(moved >= std::sqrt(2e9 * 0.7 / (1.3 * 0.4) / 2000.0)); // at least √(M/ρ0)
    CHECK(moved < 0.2 * total);
    // Elastic materials keep the total-F bound in both formulations.
    test::MaterialPoint<2> rubber("type neoHookean; mu 1e6; kappa 5e6; rho 1000;");
    CHECK(rubber.material->maxWaveSpeedSinceReference(&F, &F, 1, 0) ==
          rubber.material->maxWaveSpeed(&F, 1, 0));
}
