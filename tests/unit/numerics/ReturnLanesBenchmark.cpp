// A benchmark, not a test (hidden from the suite: the tag starts with a dot): the cost of a
// plastic material's return in lanes per gradF stress sample, in the layout gradF hands it
// (each particle's committed states in rows, padded to whole blocks of 16, a particle's 29
// samples in 2D and 57 in 3D, the next states packed, the changed flags), for elastic points
// (virgin, and with a plastic history) and for a mix where most flow, and beside them
// neoHookean's stress at the same gradients in the same batches (the elastic material the
// plastic ones are measured against: docs/performance.md, "The floor of gradF's neighbour
// samples"). Used to measure the changes of issue 30 (docs/performance.md, "The return in
// lanes: fewer instructions around the arithmetic"); the time of a whole run is
// tests/benchmarks/run's.
//   numericsTests "[.returnLanesBenchmark]"
// prints the fastest of five rounds in ns per sample. The machine's speed changes by a third
// from minute to minute: compare two builds only in alternating runs.
#include "numerics/PlasticPoints.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

using namespace sph;
using namespace sph::test;

namespace
{

// The fastest of five rounds of `repeats` calls of evaluateParticle(a) for every particle a, in
// ns per sample.
template <class EvaluateParticle>
double fastestPerSample(std::size_t particles, std::size_t count,
                        const EvaluateParticle& evaluateParticle)
{
    const int repeats = 400;
    double fastest = 1e300;
    for (int round = 0; round < 5; ++round)
    {
        const auto start = std::chrono::steady_clock::now();
        for (int r = 0; r < repeats; ++r)
        {
            for (std::size_t a = 0; a < particles; ++a)
            {
                evaluateParticle(a);
            }
        }
        const std::chrono::duration<double, std::nano> took =
            std::chrono::steady_clock::now() - start;
        fastest = std::min(fastest, took.count() / (repeats * static_cast<double>(count)));
    }
    return fastest;
}

template <int D>
void timeReturns(const char* label, const std::string& material, double amplitude, bool virgin,
                 std::size_t perParticle)
{
    constexpr std::size_t stride = PlasticState<D>::packedSize;
    const std::size_t particles = 4096 / perParticle;
    const std::size_t count = particles * perParticle;
    RandomPoints<D> points(Mat<D>::Identity(), amplitude, count, 7, false);
    if (virgin)
    {
        for (std::size_t i = 0; i < count; ++i)
        {
            PlasticState<D>{}.pack(&points.states[i * stride]);
        }
    }
    Body<D> body(material, points);
    // The rows as gradF's SampleHistory::readRows writes them.
    const std::size_t rowLength =
        (perParticle + HistoryOf::rowBlock - 1) / HistoryOf::rowBlock * HistoryOf::rowBlock;
    double initial[stride];
    PlasticState<D>{}.pack(initial);
    std::vector<double> rows(particles * rowLength * stride);
    for (std::size_t a = 0; a < particles; ++a)
    {
        for (std::size_t c = 0; c < stride; ++c)
        {
            for (std::size_t j = 0; j < rowLength; ++j)
            {
                const std::size_t sample = a * perParticle + j;
                rows[(a * stride + c) * rowLength + j] =
                    j < perParticle ? points.states[sample * stride + c] : initial[c];
            }
        }
    }
    std::vector<Mat<D>> P(count);
    std::vector<double> next(count * stride), dissipation(count);
    std::vector<std::uint8_t> changed(count);
    const double fastest =
        fastestPerSample(particles, count,
                         [&](std::size_t a)
                         {
                             const std::size_t first = a * perParticle;
                             body.material->evaluate(
                                 points.F.data() + first, P.data() + first, nullptr, perParticle,
                                 HistoryOf::samplesInRows(&rows[a * stride * rowLength], rowLength,
                                                          stride, &next[first * stride],
                                                          &dissipation[first], &changed[first]));
                         });
    std::size_t flowing = 0;
    bool finite = true;
    for (std::size_t i = 0; i < count; ++i)
    {
        flowing += dissipation[i] > 0.0 ? 1 : 0;
        finite = finite && P[i].allFinite();
    }
    std::printf("%-34s %6.2f ns/sample (%zu of %zu samples flow)\n", label, fastest, flowing,
                count);
    REQUIRE(finite);
}

// neoHookean's stresses at the points timeReturns<D> draws (same seed, amplitude and batches
// of a particle's samples): no history, no state.
template <int D>
void timeElasticStresses(const char* label, double amplitude, std::size_t perParticle)
{
    const std::size_t particles = 4096 / perParticle;
    const std::size_t count = particles * perParticle;
    const RandomPoints<D> points(Mat<D>::Identity(), amplitude, count, 7, false);
    ParticleFields<D> fields;
    fields.setSize(count);
    const auto material =
        test::build<Material<D>>("type neoHookean; mu 43.333333e9; kappa 130e9; rho 8930;",
                                 {&fields, BodyRange{"body", 0, count}, nullptr}, D);
    std::vector<Mat<D>> P(count);
    const double fastest =
        fastestPerSample(particles, count,
                         [&](std::size_t a)
                         {
                             const std::size_t first = a * perParticle;
                             material->evaluate(points.F.data() + first, P.data() + first, nullptr,
                                                perParticle, HistoryOf{});
                         });
    bool finite = true;
    for (const Mat<D>& p : P)
    {
        finite = finite && p.allFinite();
    }
    std::printf("%-34s %6.2f ns/sample\n", label, fastest);
    REQUIRE(finite);
}

} // namespace

TEST_CASE("the return in lanes per stress sample, 2D and 3D", "[.returnLanesBenchmark]")
{
    using plasticMaterials::copper;
    timeElasticStresses<2>("neoHookean 2D (no history)", 0.001, 29);
    timeReturns<2>("j2Plasticity 2D, elastic, virgin", copper, 0.001, true, 29);
    timeReturns<2>("j2Plasticity 2D, elastic", copper, 0.001, false, 29);
    timeReturns<2>("j2Plasticity 2D, most flow", copper, 0.006, false, 29);
    timeReturns<2>("druckerPrager 2D", plasticMaterials::dp, 0.001, false, 29);
    timeElasticStresses<3>("neoHookean 3D (no history)", 0.001, 57);
    timeReturns<3>("j2Plasticity 3D, elastic, virgin", copper, 0.001, true, 57);
    timeReturns<3>("j2Plasticity 3D, elastic", copper, 0.001, false, 57);
    timeReturns<3>("j2Plasticity 3D, most flow", copper, 0.006, false, 57);
    timeReturns<3>("druckerPrager 3D, virgin", plasticMaterials::dp, 0.0003, true, 57);
}
