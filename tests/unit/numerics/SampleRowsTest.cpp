// gradF's samples handed to a plastic material in rows (HistoryOf::samplesInRows, issue 30: a
// material reads a component of 16 committed states with one load instead of gathering it
// number by number). The layout must change nothing but the time:
//   - SampleHistory::readRows() is read() transposed, each row padded with the initial state's
//     component (with records and without, after commits; a particle's records one run or not);
//   - a material's evaluation of samples in rows gives the stresses, energies, dissipations,
//     `changed` flags and next states of the packed evaluation, bit for bit (both models, 2D and
//     3D, elastic and flowing points, some with a flow pressure, over counts that leave the last
//     block of 16 partly empty).
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

} // namespace

TEST_CASE("gradF samples in rows: read() transposed and padded, bit for bit", "[samples][lanes]")
{
    rowsAreReadTransposed<2>();
    rowsAreReadTransposed<3>();
}

TEST_CASE("plastic samples in rows: the packed evaluation's results, bit for bit",
          "[plasticity][lanes]")
{
    const std::string dp = "type druckerPrager; E 7.2e6; nu 0.2; rho 2000; frictionAngle 30; "
                           "dilatancyAngle 10; cohesion 1e4;";
    const std::string hardening = "type j2Plasticity; E 200e9; nu 0.3; rho 7800; yieldStress 2e8; "
                                  "hardeningModulus 1e9;";
    const Mat<2> identity = Mat<2>::Identity();
    const Mat<3> identity3 = Mat<3>::Identity();
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
