// gradF's samples handed to a plastic material in rows (HistoryOf::samplesInRows, issue 30: a
// material reads a component of 16 committed states with one load instead of gathering it
// number by number). The layout must change nothing but the time:
//   - SampleHistory::readRows() is read() transposed, each row padded with the initial state's
//     component (with records and without, after commits; a particle's records one run or not);
//   - a material's evaluation of samples in rows gives the stresses, energies, dissipations,
//     `changed` flags and next states of the packed evaluation, bit for bit (both models, 2D and
//     3D, elastic and flowing points, some with a flow pressure, over counts that leave the last
//     block of 16 partly empty);
//   - at most half a block (gradF's moment points) is evaluated in 8 lanes, packed or in a half
//     row, with the results of the same points in a whole block of 16, bit for bit.
#include "numerics/PlasticPoints.hpp"
#include "numerics/SampleHistorySupport.hpp"

using namespace sph;

namespace
{

std::size_t rowsFor(std::size_t count)
{
    return (count + HistoryOf::rowBlock - 1) / HistoryOf::rowBlock * HistoryOf::rowBlock;
}

template <int D>
void rowsAreReadTransposed()
{
    INFO(D << "D");
    using namespace test::samples;
    Samples<D> s(5);
    std::mt19937 random(11);
    for (int round = 0; round < 3; ++round)
    {
        evaluate<D>(s, round, random);
        s.history.commit();
        // After the third round every sample has a record, relocated into slot order: each
        // particle's are read as one run (the other path before).
        std::size_t runs = 0;
        for (std::size_t a = 0; a < s.x.size(); ++a)
        {
            runs += s.history.fromOneRun(s.list.begin(a), s.list.count(a)) ? 1 : 0;
        }
        CHECK(runs == (round == 2 ? s.x.size() : 0));
        for (std::size_t a = 0; a < s.x.size(); ++a)
        {
            const std::vector<double> packed = s.read(a);
            const std::size_t count = s.list.count(a);
            const std::size_t length = rowsFor(count) + (a % 2 == 0 ? 0 : HistoryOf::rowBlock);
            std::vector<double> got(length * s.stride, -1.0);
            s.history.readRows(s.list.begin(a), count, got.data(), length);
            const std::vector<double> want = inRows(packed, s.stride, length, s.initial());
            REQUIRE(sameBits(got.data(), want.data(), want.size()));
        }
    }
    CHECK(s.history.storedStates() > 0);
}

// The points as stress samples, packed and in rows (every third with a flow pressure), compared
// bit for bit; returns how many flow.
template <int D>
std::size_t samplesInRowsAsPacked(const std::string& materialText, const Mat<D>& centre,
                                  double amplitude, std::size_t count, unsigned seed)
{
    constexpr std::size_t stride = PlasticState<D>::packedSize;
    test::RandomPoints<D> points(centre, amplitude, count, seed, false);
    for (std::size_t i = 0; i < count; i += 3)
    {
        points.states[i * stride + PlasticState<D>::flowPressureAt] = -1234.5;
    }
    std::vector<double> initial(stride);
    PlasticState<D>{}.pack(initial.data());
    const std::size_t rowLength = rowsFor(count);
    const std::vector<double> rows = test::samples::inRows(points.states, stride, rowLength, initial);
    test::Body<D> body(materialText, points);
    std::vector<Mat<D>> P(count), PRows(count);
    std::vector<double> psi(count), psiRows(count), dissipation(count), dissipationRows(count);
    std::vector<double> next(count * stride, -7.25), nextRows(count * stride, -7.25);
    std::vector<std::uint8_t> changed(count, 2), changedRows(count, 3);
    body.material->evaluate(points.F.data(), P.data(), psi.data(), count,
                            HistoryOf::samples(points.states.data(), stride, next.data(),
                                               dissipation.data(), changed.data()));
    body.material->evaluate(points.F.data(), PRows.data(), psiRows.data(), count,
                            HistoryOf::samplesInRows(rows.data(), rowLength, stride, nextRows.data(),
                                                     dissipationRows.data(), changedRows.data()));
    std::size_t flowing = 0;
    for (std::size_t i = 0; i < count; ++i)
    {
        INFO("point " << i << " of " << count);
        CHECK(test::sameBits(PRows[i], P[i]));
        CHECK(test::sameBits(psiRows[i], psi[i]));
        CHECK(test::sameBits(dissipationRows[i], dissipation[i]));
        REQUIRE(changedRows[i] == changed[i]);
        for (std::size_t c = 0; c < stride; ++c)
        {
            CHECK(test::sameBits(nextRows[i * stride + c], next[i * stride + c]));
        }
        flowing += dissipation[i] > 0.0 ? 1 : 0;
    }
    return flowing;
}

// At most half a block of samples (gradF's moment points) is evaluated in half as many lanes,
// packed or in a half row: each point's results are those of the same point in a whole block
// of 16, bit for bit (a lane does not depend on the width). Returns how many of them flow.
template <int D>
std::size_t halfBlockAsWhole(const std::string& materialText, const Mat<D>& centre,
                             double amplitude, std::size_t count, unsigned seed)
{
    constexpr std::size_t stride = PlasticState<D>::packedSize;
    constexpr std::size_t whole = HistoryOf::rowBlock;
    REQUIRE(count <= whole / 2);
    test::RandomPoints<D> points(centre, amplitude, whole, seed, false);
    std::vector<double> initial(stride);
    PlasticState<D>{}.pack(initial.data());
    test::Body<D> body(materialText, points);
    struct Results
    {
        std::vector<Mat<D>> P;
        std::vector<double> psi, dissipation, next;
        std::vector<std::uint8_t> changed;
        explicit Results(std::size_t n)
            : P(n), psi(n), dissipation(n), next(n * stride, -7.25), changed(n, 2)
        {
        }
    };
    Results all(whole), packed(count), rows(count);
    body.material->evaluate(points.F.data(), all.P.data(), all.psi.data(), whole,
                            HistoryOf::samples(points.states.data(), stride, all.next.data(),
                                               all.dissipation.data(), all.changed.data()));
    body.material->evaluate(points.F.data(), packed.P.data(), packed.psi.data(), count,
                            HistoryOf::samples(points.states.data(), stride, packed.next.data(),
                                               packed.dissipation.data(), packed.changed.data()));
    const std::vector<double> firstStates(points.states.begin(),
                                          points.states.begin() + static_cast<long>(count * stride));
    const std::vector<double> halfRows = test::samples::inRows(firstStates, stride, whole / 2, initial);
    body.material->evaluate(points.F.data(), rows.P.data(), rows.psi.data(), count,
                            HistoryOf::samplesInRows(halfRows.data(), whole / 2, stride,
                                                     rows.next.data(), rows.dissipation.data(),
                                                     rows.changed.data()));
    std::size_t flowing = 0;
    for (const Results* r : {&packed, &rows})
    {
        for (std::size_t i = 0; i < count; ++i)
        {
            INFO("point " << i << " of " << count << (r == &rows ? ", in rows" : ", packed"));
            CHECK(test::sameBits(r->P[i], all.P[i]));
            CHECK(test::sameBits(r->psi[i], all.psi[i]));
            CHECK(test::sameBits(r->dissipation[i], all.dissipation[i]));
            REQUIRE(r->changed[i] == all.changed[i]);
            for (std::size_t c = 0; c < stride; ++c)
            {
                CHECK(test::sameBits(r->next[i * stride + c], all.next[i * stride + c]));
            }
        }
    }
    for (std::size_t i = 0; i < count; ++i)
    {
        flowing += all.dissipation[i] > 0.0 ? 1 : 0;
    }
    return flowing;
}

// The two materials of the evaluations in rows: a frictional one, and steel with hardening.
const std::string dp = "type druckerPrager; E 7.2e6; nu 0.2; rho 2000; frictionAngle 30; "
                       "dilatancyAngle 10; cohesion 1e4;";
const std::string hardening = "type j2Plasticity; E 200e9; nu 0.3; rho 7800; yieldStress 2e8; "
                              "hardeningModulus 1e9;";
const Mat<2> identity = Mat<2>::Identity();
const Mat<3> identity3 = Mat<3>::Identity();

} // namespace

TEST_CASE("plastic samples: half a block in half the lanes gives a whole block's results, bit "
          "for bit",
          "[plasticity][lanes]")
{
    std::size_t flowing = 0;
    for (unsigned seed = 1; seed <= 4; ++seed)
    {
        flowing += halfBlockAsWhole<2>(dp, identity, 0.01, 5, seed);
        flowing += halfBlockAsWhole<3>(dp, identity3, 0.0015, 7, seed);
        flowing += halfBlockAsWhole<2>(hardening, identity, 0.0008, 5, seed);
        flowing += halfBlockAsWhole<3>(hardening, identity3, 0.0008, 8, seed);
    }
    CHECK(flowing > 8); // flowing points among them, and elastic ones:
    CHECK(flowing < 4 * (5 + 7 + 5 + 8));
}

TEST_CASE("gradF samples in rows: read() transposed and padded, bit for bit", "[samples][lanes]")
{
    rowsAreReadTransposed<2>();
    rowsAreReadTransposed<3>();
}

TEST_CASE("plastic samples in rows: the packed evaluation's results, bit for bit",
          "[plasticity][lanes]")
{
    const std::size_t dp2 = samplesInRowsAsPacked<2>(dp, identity, 0.01, 29, 1);
    CHECK(dp2 > 3);
    CHECK(dp2 < 26);
    CHECK(samplesInRowsAsPacked<3>(dp, identity3, 0.0015, 21, 9) > 3);
    const std::size_t j2 = samplesInRowsAsPacked<2>(hardening, identity, 0.0008, 27, 5);
    CHECK(j2 > 3);
    CHECK(j2 < 24);
    CHECK(samplesInRowsAsPacked<3>(hardening, identity3, 0.0008, 45, 7) > 3);
    // Elastic everywhere (every block takes the return's shortcut).
    CHECK(samplesInRowsAsPacked<2>(hardening, identity, 1e-5, 18, 3) == 0);
}
