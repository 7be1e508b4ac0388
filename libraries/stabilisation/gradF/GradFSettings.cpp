// gradF's description, keys and their checks (the constructor): what a case can set and what
// it is refused, with file:line and a hint. The scheme itself is GradF.cpp.
#include "stabilisation/gradF/GradF.hpp"

namespace sph
{

template <int D>
std::string GradF<D>::description()
{
    return "The seed paper's gradient-of-F stabilisation (Saito & Kusachi 2017): energy "
           "sum_a V0_a sum_b W^_ab Psi(F_a + G_a x_ba), exact force of spec §6.4. No tuning "
           "parameter.";
}

template <int D>
Schema GradF<D>::schema()
{
    return Schema().add(Key::word("plasticSamples",
                                  "materials with history: ownHistory (every stress sample keeps "
                                  "its own; exact energy), elasticState (plastic flow: samples "
                                  "carry their elastic state and extrapolate only the motion "
                                  "since the last reference move (updated Lagrangian) or the "
                                  "last step (total Lagrangian, §G25) instead of the total "
                                  "gradient of F; docs/theory/gradF-plastic.md) or linearised "
                                  "(the return's "
                                  "correction at F_a, linearised; for comparison)")
                            .choices({"ownHistory", "elasticState", "linearised"})
                            .defaultValue("ownHistory"))
        .add(Key::word("moveWeights",
                       "plasticSamples elasticState: the samples' energy weights at a reference "
                       "move: kernel (the new reference's kernel weights, as the paper; "
                       "consistent, a move may change the energy), conserving (chosen so that no "
                       "move changes the energy; the quadrature then lags the configuration) or "
                       "nonIncreasing (so that no move raises it); "
                       "docs/theory/gradF-plastic.md §G9")
                 .choices({"kernel", "conserving", "nonIncreasing"})
                 .defaultValue("kernel"))
        .add(Key::word("openedSamples",
                       "plasticSamples elasticState: the samples of an opened particle (sand "
                       "beyond its tension cut-off): own (their own states) or particle (at each "
                       "move they take its state, the energy they held booked as dissipated; "
                       "docs/theory/gradF-plastic.md §G22)")
                 .choices({"own", "particle"})
                 .defaultValue("own"))
        .add(Key::word("sampleVolume",
                       "the volume change of the stress samples: own (each sample's det F_b(a), "
                       "as the paper) or particle (every sample of a particle takes the "
                       "particle's det F_a, the F-bar method: the samples' spread stays isochoric, "
                       "so isochoric plastic flow does not lock; it acts on bodies whose material "
                       "has a plastic history, 2D and 3D; with `impenetrability` in sphSchemes, "
                       "docs/theory/gradF-plastic.md §G13-§G14)")
                 .choices({"own", "particle"})
                 .defaultValue("own"))
        .add(Key::word("fit",
                       "how F_a and its gradient are fitted to the neighbours: sequential (as the "
                       "paper: F_a the corrected gradient, then its gradient by least squares with "
                       "F_a fixed) or joint (both from one least-squares fit of the second-order "
                       "Taylor expansion: the stress samples exact for quadratic motions at free "
                       "surfaces and on disordered neighbourhoods too, where the sequential fit's "
                       "carry a first-order error; docs/theory/gradF-plastic.md §G17)")
                 .choices({"sequential", "joint"})
                 .defaultValue("sequential"))
        .add(Key::word("samplePoints",
                       "where the stress is sampled around a particle: neighbours (at every "
                       "neighbour, as the paper) or moments (at 2D + 1 points with the same "
                       "moments of the kernel weights up to the second: the same energy for "
                       "every strain energy quadratic in F, 6-8x fewer stress evaluations; "
                       "total Lagrangian with any material, updated Lagrangian without plastic "
                       "history or with plasticSamples elasticState (the points turn with the "
                       "material and carry their states); docs/theory/gradF-moments.md)")
                 .choices({"neighbours", "moments"})
                 .defaultValue("neighbours"));
}

template <int D>
GradF<D>::GradF(const Params& params, const typename Stabilisation<D>::Args& args)
    : linearised_(params.word("plasticSamples") == "linearised"),
      elasticState_(params.word("plasticSamples") == "elasticState"),
      referenceMoves_(args.referenceMoves),
      weights_(!elasticState_ || params.word("moveWeights") == "kernel" ? MoveWeights::kernel
               : params.word("moveWeights") == "conserving"                ? MoveWeights::conserving
                                                                           : MoveWeights::nonIncreasing),
      openedFromParticle_(params.word("openedSamples") == "particle"),
      particleVolume_(params.word("sampleVolume") == "particle"),
      jointFit_(params.word("fit") == "joint"),
      samplePointsWhere_(params.location("samplePoints"))
{
    // Total-Lagrangian elasticState's samples are the pairs' own: their frames (§G25) are the
    // neighbours' positions, which moment points are not (§M4). In updated Lagrangian form the
    // points carry their states across the moves (§M7), but not an opened neighbour's state
    // (§G22: a pair's).
    moments_.activate(params.word("samplePoints") == "moments");
    if (moments_.active() && elasticState_ && !referenceMoves_)
    {
        params.fail("samplePoints",
                    "samplePoints moments samples the stress at points that are not neighbours, "
                    "but plasticSamples elasticState in total Lagrangian form frames each "
                    "sample at its neighbour's position (docs/theory/gradF-moments.md §M4)",
                    {"hint: use plasticSamples ownHistory (the default) with formulation "
                     "totalLagrangian, formulation updatedLagrangian (§M7), or remove "
                     "samplePoints (neighbours, the default)"});
    }
    if (moments_.active() && openedFromParticle_)
    {
        params.fail("openedSamples",
                    "openedSamples particle gives the sample of a pair a-b the state of an "
                    "opened neighbour b, and samplePoints moments samples at points, not at "
                    "neighbours (docs/theory/gradF-moments.md §M7)",
                    {"hint: remove openedSamples (own, the default), or samplePoints "
                     "(neighbours, the default)"});
    }
    // Only samples that carry their elastic state have weights to choose.
    if (!elasticState_ && params.given("moveWeights") && params.word("moveWeights") != "kernel")
    {
        params.fail("moveWeights",
                    "moveWeights " + params.word("moveWeights") +
                        " chooses the energy weights of samples that carry their elastic state, "
                        "but plasticSamples is " + params.word("plasticSamples"),
                    {"hint: add 'plasticSamples elasticState;' or remove moveWeights"});
    }
    if (!elasticState_ && openedFromParticle_)
    {
        params.fail("openedSamples",
                    "openedSamples particle gives the samples of an opened particle its state "
                    "at each reference move, which only samples that carry their elastic state "
                    "across the moves have, but plasticSamples is " +
                        params.word("plasticSamples"),
                    {"hint: add 'plasticSamples elasticState;' (with formulation "
                     "updatedLagrangian) or remove openedSamples"});
    }
    // Both act at reference moves, which a total-Lagrangian run never makes (its elasticState
    // frames move at the commits, §G25, with the reference's fixed weights).
    if (!referenceMoves_ && params.given("moveWeights") && params.word("moveWeights") != "kernel")
    {
        params.fail("moveWeights",
                    "moveWeights " + params.word("moveWeights") +
                        " chooses the samples' energy weights at each reference move, and "
                        "formulation totalLagrangian never moves its reference",
                    {"hint: remove moveWeights (kernel, the default), or use formulation "
                     "updatedLagrangian"});
    }
    if (!referenceMoves_ && openedFromParticle_)
    {
        params.fail("openedSamples",
                    "openedSamples particle acts at each reference move, and formulation "
                    "totalLagrangian never moves its reference",
                    {"hint: remove openedSamples (own, the default), or use formulation "
                     "updatedLagrangian"});
    }
    // In 1D F̄_b(a) = (J_a / F_b) F_b = F_a for every sample: nothing of gradF would be left.
    if (D == 1 && particleVolume_)
    {
        params.fail("sampleVolume",
                    "sampleVolume particle in 1D gives every stress sample the particle's F "
                    "(a volume ratio is all a 1D F has), which removes gradF's stabilisation",
                    {"hint: remove sampleVolume (own, the default) in a 1D case"});
    }
}

template std::string GradF<1>::description();
template std::string GradF<2>::description();
template std::string GradF<3>::description();
template Schema GradF<1>::schema();
template Schema GradF<2>::schema();
template Schema GradF<3>::schema();
template GradF<1>::GradF(const Params&, const typename Stabilisation<1>::Args&);
template GradF<2>::GradF(const Params&, const typename Stabilisation<2>::Args&);
template GradF<3>::GradF(const Params&, const typename Stabilisation<3>::Args&);

} // namespace sph
