// The returns in lanes (libraries/materials/plasticity/ReturnLanes.hpp, ReturnMapLanes.hpp and
// the paths through them, ReturnMapPaths.hpp).
// Every return of a plastic material runs the same code, eight points at a time (a particle's
// stress samples, a chunk of particles) or one at a time (returnMap: the wave speed or the
// commit of a particle the memo does not hold, e.g. after a restart). A point must give the
// same digits either way, or a restarted run would not repeat the run it continues:
//   - eight at a time = one at a time, bit for bit (wave speeds and committed states with and
//     without the memo of the force evaluation), and a body's samples = its particles, bit
//     for bit;
//   - a sample marked unchanged (HistoryOf::changed) would commit its committed state, bit for
//     bit, and the others' next states are those of an evaluation that writes them all;
//   - elastic samples are `hencky`'s to round-off (an independent path: Eigen's eigen-solver
//     where the lanes use Jacobi rotations in 3D), also at a double eigenvalue (uniaxial).
// On every branch of the returns: elastic points, flowing ones, the cone and the apex of
// druckerPrager (also a cohesionless one pulled apart), j2Plasticity's hardening and its
// exhausted softening; over counts that leave the last chunk partly empty. The returns
// themselves are checked against hand-computed cases in DruckerPragerTest and PlasticityTest.
#include "numerics/PlasticPoints.hpp"

using namespace sph;

namespace
{
using test::Body;
using test::RandomPoints;
using test::sameBits;

// The points through every path, compared bit for bit; returns the number that flow.
template <int D>
std::size_t compareThePaths(const std::string& materialText, const Mat<D>& centre, double amplitude,
                            std::size_t count, unsigned seed, bool uniaxial = false)
{
    constexpr std::size_t stride = PlasticState<D>::packedSize;
    const RandomPoints<D> points(centre, amplitude, count, seed, uniaxial);
    const double V0 = 1.0;

    // One at a time: nothing in the memo, so the wave speed and the commit run returnMap.
    Body<D> alone(materialText, points);
    std::vector<double> speedAlone(count), dissipatedAlone(count), nextAlone(count * stride);
    for (std::size_t i = 0; i < count; ++i)
    {
        speedAlone[i] = alone.material->maxWaveSpeed(&points.F[i], 1, i);
        dissipatedAlone[i] = alone.material->commit(&points.F[i], &V0, i, 1);
        alone.material->packHistory(i, &nextAlone[i * stride]);
    }

    // Eight at a time: the particles' force evaluation, then the wave speed and the commit from
    // its memo.
    Body<D> batched(materialText, points);
    std::vector<Mat<D>> P(count);
    std::vector<double> psi(count);
    batched.material->evaluate(points.F.data(), P.data(), psi.data(), count, HistoryOf::particles(0));
    // The same points as a body's stress samples.
    std::vector<Mat<D>> sampleP(count);
    std::vector<double> samplePsi(count), sampleNext(count * stride, -1.0), sampleDissipation(count, -1.0);
    batched.material->evaluate(points.F.data(), sampleP.data(), samplePsi.data(), count,
                               HistoryOf::samples(points.states.data(), stride, sampleNext.data(),
                                                  sampleDissipation.data()));

    std::size_t flowing = 0;
    for (std::size_t i = 0; i < count; ++i)
    {
        INFO("point " << i << " of " << count);
        CHECK(sameBits(batched.material->maxWaveSpeed(&points.F[i], 1, i), speedAlone[i]));
        CHECK(sameBits(batched.material->commit(&points.F[i], &V0, i, 1), dissipatedAlone[i]));
        CHECK(sameBits(sampleDissipation[i], dissipatedAlone[i]));
        CHECK(sameBits(sampleP[i], P[i]));
        CHECK(sameBits(samplePsi[i], psi[i]));
        double next[stride];
        batched.material->packHistory(i, next);
        for (std::size_t k = 0; k < stride; ++k)
        {
            CHECK(sameBits(next[k], nextAlone[i * stride + k]));
            CHECK(sameBits(sampleNext[i * stride + k], nextAlone[i * stride + k]));
        }
        // A flowing point commits a new Cp⁻¹ (at the apex of a cohesionless cone it flows
        // without dissipating).
        flowing += std::equal(next, next + D * D, &points.states[i * stride]) ? 0 : 1;
    }
    return flowing;
}

// Elastic samples from the virgin state against `hencky` with the same constants (its
// principal strains from Eigen's eigen-solver, the law written once more).
template <int D>
void compareWithHencky(const std::string& elasticConstants, const std::string& plasticKeys,
                       double amplitude, std::size_t count, unsigned seed, bool uniaxial)
{
    RandomPoints<D> points(Mat<D>::Identity(), amplitude, count, seed, uniaxial);
    std::fill(points.states.begin(), points.states.end(), 0.0);
    for (std::size_t i = 0; i < count; ++i)
    {
        PlasticState<D>{}.pack(&points.states[i * PlasticState<D>::packedSize]);
    }
    Body<D> plastic(elasticConstants + plasticKeys, points);
    ParticleFields<D> fields;
    fields.setSize(count);
    const auto hencky = test::build<Material<D>>("type hencky; " + elasticConstants,
                                                 {&fields, BodyRange{"body", 0, count}, nullptr}, D);
    std::vector<Mat<D>> P(count);
    std::vector<double> psi(count), next(points.states.size()), dissipation(count);
    plastic.material->evaluate(points.F.data(), P.data(), psi.data(), count,
                               HistoryOf::samples(points.states.data(), PlasticState<D>::packedSize,
                                                  next.data(), dissipation.data()));
    for (std::size_t i = 0; i < count; ++i)
    {
        INFO("point " << i << " of " << count);
        REQUIRE(dissipation[i] == 0.0);
        const Mat<D> expected = hencky->stress(points.F[i]);
        CHECK((P[i] - expected).norm() <= 1e-12 * expected.norm() + 1e-14 * hencky->youngsModulus());
        const double energy = hencky->energy(points.F[i]);
        CHECK(std::abs(psi[i] - energy) <= 1e-12 * energy + 1e-14 * expected.norm());
    }
}

const Mat<2> identity = Mat<2>::Identity();

Mat<2> scaled(double s) { return s * Mat<2>::Identity(); }

const Mat<3> identity3 = Mat<3>::Identity();

// HistoryOf::changed (what gradF's samples hand the material so that a commit compares only the
// states that may change): the points as stress samples with and without it. Where a point is
// marked unchanged, the state its commit would make is its committed one bit for bit, and its
// `next` is left as it was; elsewhere `next`, and everything else, is the same either way. Every
// third point's committed state carries a flow pressure (a druckerPrager point that flowed
// before), which a point that does not flow now drops: marked changed. Returns the number of
// points marked unchanged.
template <int D>
std::size_t checkTheChangedStates(const std::string& materialText, const Mat<D>& centre,
                                  double amplitude, std::size_t count, unsigned seed)
{
    constexpr std::size_t stride = PlasticState<D>::packedSize;
    RandomPoints<D> points(centre, amplitude, count, seed, false);
    for (std::size_t i = 0; i < count; i += 3)
    {
        points.states[i * stride + PlasticState<D>::flowPressureAt] = -1234.5;
    }
    Body<D> body(materialText, points);
    std::vector<Mat<D>> P(count), PMarked(count);
    std::vector<double> psi(count), psiMarked(count);
    std::vector<double> next(count * stride), dissipation(count), dissipationMarked(count);
    const double untouched = -7.25;
    std::vector<double> nextMarked(count * stride, untouched);
    std::vector<std::uint8_t> changed(count, 2);
    body.material->evaluate(points.F.data(), P.data(), psi.data(), count,
                            HistoryOf::samples(points.states.data(), stride, next.data(),
                                               dissipation.data()));
    body.material->evaluate(points.F.data(), PMarked.data(), psiMarked.data(), count,
                            HistoryOf::samples(points.states.data(), stride, nextMarked.data(),
                                               dissipationMarked.data(), changed.data()));
    std::size_t unchanged = 0;
    for (std::size_t i = 0; i < count; ++i)
    {
        INFO("point " << i << " of " << count);
        REQUIRE((changed[i] == 0 || changed[i] == 1));
        CHECK(sameBits(P[i], PMarked[i]));
        CHECK(sameBits(psi[i], psiMarked[i]));
        CHECK(sameBits(dissipation[i], dissipationMarked[i]));
        for (std::size_t c = 0; c < stride; ++c)
        {
            const double written = next[i * stride + c];
            if (changed[i] == 0)
            {
                CHECK(sameBits(written, points.states[i * stride + c]));
                CHECK(nextMarked[i * stride + c] == untouched);
            }
            else
            {
                CHECK(sameBits(written, nextMarked[i * stride + c]));
            }
        }
        unchanged += changed[i] == 0 ? 1 : 0;
    }
    return unchanged;
}

} // namespace

TEST_CASE("returns in lanes: druckerPrager, eight points at a time as one at a time, bit for bit",
          "[plasticity][lanes]")
{
    const std::string dp = "type druckerPrager; E 7.2e6; nu 0.2; rho 2000; frictionAngle 30; "
                           "dilatancyAngle 10; cohesion 1e4;";
    // Sheared around the identity: some points elastic, some on the cone.
    const std::size_t sheared = compareThePaths<2>(dp, identity, 0.01, 29, 1);
    CHECK(sheared > 3);
    CHECK(sheared < 26);
    // Pulled apart: past the apex (the capped branch).
    CHECK(compareThePaths<2>(dp, scaled(1.02), 0.003, 13, 2) > 10);
    // Cohesionless, ψ = 0: open voids, and compressed flow.
    const std::string sand = "type druckerPrager; E 0.84e6; nu 0.3; rho 2650; frictionAngle 19.8; "
                             "cohesion 0;";
    CHECK(compareThePaths<2>(sand, scaled(1.01), 0.02, 8, 3) > 4);
    CHECK(compareThePaths<2>(sand, scaled(0.99), 0.02, 17, 4) > 4);
    // 3D: the cone and the apex.
    const std::size_t cone = compareThePaths<3>(dp, identity3, 0.0015, 21, 9);
    CHECK(cone > 3);
    CHECK(cone < 18);
    CHECK(compareThePaths<3>(dp, 1.02 * identity3, 0.003, 11, 10) > 8);
    // Only the samples that flow, or drop a flow pressure, are compared at the commit.
    // (Both kinds among the points: a third carry a flow pressure, some flow.)
    const std::size_t kept2 = checkTheChangedStates<2>(dp, identity, 0.01, 29, 1);
    CHECK(kept2 > 0);
    CHECK(kept2 < 20);
    const std::size_t kept3 = checkTheChangedStates<3>(dp, identity3, 0.0015, 21, 9);
    CHECK(kept3 > 0);
    CHECK(kept3 < 14);
}

TEST_CASE("returns in lanes: j2Plasticity, eight points at a time as one at a time, bit for bit",
          "[plasticity][lanes]")
{
    const std::string hardening = "type j2Plasticity; E 200e9; nu 0.3; rho 7800; yieldStress 2e8; "
                                  "hardeningModulus 1e9;";
    const std::size_t flowing = compareThePaths<2>(hardening, identity, 0.0008, 27, 5);
    CHECK(flowing > 3);
    CHECK(flowing < 24);
    // Softening to exhaustion: σy reaches 0, the deviator vanishes.
    const std::string softening = "type j2Plasticity; E 200e9; nu 0.3; rho 7800; yieldStress 2e8; "
                                  "hardeningModulus -1e11;";
    CHECK(compareThePaths<2>(softening, identity, 0.02, 9, 6) > 4);
    const std::string copper = "type j2Plasticity; E 117e9; nu 0.35; rho 8930; yieldStress 0.4e9; "
                               "hardeningModulus 0.1e9;";
    const std::size_t copperFlowing = compareThePaths<3>(copper, identity3, 0.003, 29, 7);
    CHECK(copperFlowing > 3);
    CHECK(copperFlowing < 26);
    // Uniaxial stretches from the virgin state: two equal principal stretches.
    CHECK(compareThePaths<3>(copper, identity3, 0.01, 16, 8, true) > 8);
    // Only the samples that flow, or drop a flow pressure, are compared at the commit.
    CHECK(checkTheChangedStates<2>(hardening, identity, 0.0008, 27, 5) > 3);
    CHECK(checkTheChangedStates<3>(copper, identity3, 0.003, 29, 7) > 3);
}

TEST_CASE("returns in lanes: elastic points are hencky's (2D, and 3D with Jacobi rotations)",
          "[plasticity][lanes]")
{
    const std::string copper = "E 117e9; nu 0.35; rho 8930; ";
    const std::string j2 = "type j2Plasticity; yieldStress 4e9;";
    compareWithHencky<2>(copper, j2, 0.01, 19, 11, false);
    compareWithHencky<3>(copper, j2, 0.01, 19, 12, false);
    compareWithHencky<3>(copper, j2, 0.01, 13, 13, true);
    const std::string sand = "E 0.84e6; nu 0.3; rho 2650; ";
    compareWithHencky<3>(sand, "type druckerPrager; frictionAngle 30; cohesion 1e6;", 0.01, 11, 14, true);
}
