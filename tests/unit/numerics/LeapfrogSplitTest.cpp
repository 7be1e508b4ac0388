// The leapfrog's kick split at a level (updatedLagrangian splitKick, docs/theory/gradF-plastic.md
// §G20): closeAtLevel() closes the step that ended with its own acceleration, so the stored
// velocity is v^n (what synchronise() reports, whatever the level's acceleration), and the next
// advance() kicks half a step from it:
//   v^n = v^{n-1/2} + ½Δt_{n-1} a_close,   v^{n+1/2} = v^n + ½Δt_n a^n.
// Without the split the level's kick is the one ½(Δt_{n-1} + Δt_n) a^n.
#include "numerics/NumericsSupport.hpp"
#include "timeIntegration/TimeIntegration.hpp"

using namespace sph;

namespace
{

struct Integrator
{
    std::vector<Vec<2>> v{Vec<2>(1.0, -2.0), Vec<2>(0.25, 0.5)};
    ParticleFields<2> fields;
    RunScalars scalars;
    std::unique_ptr<TimeIntegration<2>> leapfrog;

    Integrator()
    {
        fields.resize(v.size());
        leapfrog = test::build<TimeIntegration<2>>("type leapfrog;", {0.3, 1}, 2);
        leapfrog->attach(v, fields, scalars);
    }
    // Δt from the wave-speed bound: courant h / c = 0.3 * 0.1 / c.
    double step(long n, double c)
    {
        const WaveSpeedBound bound{0.1, [c] { return c; }, [] { return std::size_t{0}; }};
        REQUIRE(leapfrog->chooseTimeStep(n, n == 0, bound).ok());
        return leapfrog->deltaT();
    }
};

} // namespace

TEST_CASE("leapfrog: the kick split at a level closes with its own acceleration", "[splitKick]")
{
    Integrator run;
    REQUIRE(run.leapfrog->splitsKicks());
    const std::vector<std::uint8_t> fixed(2, 0);
    std::vector<Vec<2>> x{Vec<2>(0.0, 0.0), Vec<2>(1.0, 0.0)};
    const std::vector<Vec<2>> a0{Vec<2>(3.0, 1.0), Vec<2>(-1.0, 2.0)};
    const std::vector<Vec<2>> aClose{Vec<2>(-2.0, 0.5), Vec<2>(4.0, -1.0)};
    const std::vector<Vec<2>> aOpen{Vec<2>(1.5, -3.0), Vec<2>(0.5, 0.25)};

    const std::vector<Vec<2>> v0 = run.v;
    const double dt0 = run.step(0, 2.0);
    run.leapfrog->advance(dt0, a0, fixed, x); // v^{1/2} = v^0 + ½Δt_0 a^0
    const double dt1 = run.step(1, 4.0);      // a different step: the halves differ
    REQUIRE(dt1 != dt0);

    run.leapfrog->closeAtLevel(aClose);
    std::vector<Vec<2>> vn(2);
    run.leapfrog->synchronise(aOpen, vn); // v^1, not v^{1/2} + ½Δt_0 aOpen
    for (std::size_t i = 0; i < 2; ++i)
    {
        const Vec<2> half = v0[i] + 0.5 * dt0 * a0[i];
        const Vec<2> level = half + 0.5 * dt0 * aClose[i];
        CHECK((vn[i] - level).norm() < 1e-15);
    }
    const std::vector<Vec<2>> closed = run.v;
    run.leapfrog->advance(dt1, aOpen, fixed, x);
    for (std::size_t i = 0; i < 2; ++i)
    {
        CHECK((run.v[i] - (closed[i] + 0.5 * dt1 * aOpen[i])).norm() < 1e-15);
    }
    // At the next level: a second close there does nothing more (the velocity is already v^n),
    // and the advance after it kicks ½Δt_2 from v^2.
    const double dt2 = run.step(2, 4.0);
    std::vector<Vec<2>> before = run.v;
    run.leapfrog->closeAtLevel(aClose);
    run.leapfrog->closeAtLevel(aClose);
    for (std::size_t i = 0; i < 2; ++i)
    {
        CHECK((run.v[i] - (before[i] + 0.5 * dt1 * aClose[i])).norm() < 1e-15);
    }
    before = run.v;
    run.leapfrog->advance(dt2, aOpen, fixed, x);
    for (std::size_t i = 0; i < 2; ++i)
    {
        CHECK((run.v[i] - (before[i] + 0.5 * dt2 * aOpen[i])).norm() < 1e-15);
    }
    // A level without a split: one kick of ½(Δt_2 + Δt_3) a^3 from v^{5/2}.
    const double dt3 = run.step(3, 2.0);
    before = run.v;
    run.leapfrog->advance(dt3, a0, fixed, x);
    for (std::size_t i = 0; i < 2; ++i)
    {
        CHECK((run.v[i] - (before[i] + 0.5 * (dt2 + dt3) * a0[i])).norm() < 1e-15);
    }
}
