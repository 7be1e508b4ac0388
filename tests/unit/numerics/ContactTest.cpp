// Contact repulsion (spec §9, §12): zero beyond the kernel support, equal and opposite
// (momentum conserved), repulsive, fixed particles untouched, and no search at all for a single
// body or bodies whose grown bounding boxes do not overlap.
#include "contact/Contact.hpp"
#include "numerics/NumericsSupport.hpp"

using namespace sph;

namespace
{

// Two 2D bodies of 6x6 particles (spacing 1), body B shifted by `gap` along x; masses and J
// vary from particle to particle.
ParticleSet<2> twoBlocks(double gap)
{
    const auto block = test::lattice<2>(6, 0.1, 3);
    ParticleSet<2> p;
    p.resize(2 * block.size());
    for (std::size_t i = 0; i < block.size(); ++i)
    {
        for (int body = 0; body < 2; ++body)
        {
            const std::size_t a = i + static_cast<std::size_t>(body) * block.size();
            p.X[a] = block[i] + Vec<2>(body * (5.0 + gap), 0.0);
            p.x[a] = p.X[a];
            p.V0[a] = 1.0 + 0.1 * std::sin(3.0 * a);
            p.m[a] = (body ? 1200.0 : 1000.0) * p.V0[a];
            p.body[a] = body;
            p.F[a] << 1.0 + 0.02 * std::cos(a), 0.01, -0.01, 1.0 - 0.03 * std::sin(a);
        }
    }
    p.bodies = {BodyRange{"A", 0, block.size()}, BodyRange{"B", block.size(), 2 * block.size()}};
    return p;
}

std::unique_ptr<Contact<2>> repulsion(const Kernel& kernel, const std::string& extra = "")
{
    return test::build<Contact<2>>("type repulsion; kappa 1e6; " + extra,
                                   {&kernel, std::vector<std::string>{"A", "B"}}, 2,
                                   Selection::withBodies({"A", "B"}));
}

} // namespace

TEST_CASE("repulsion is equal and opposite, repulsive, and spares fixed particles", "[contact]")
{
    const auto kernel = test::makeKernel("cubicSpline", 2, 1.0, 1.5);
    auto contact = repulsion(*kernel);
    ParticleSet<2> p = twoBlocks(0.5); // gaps of 1.5 spacings: within the support 3
    p.v.assign(p.size(), Vec<2>::Zero());
    std::vector<Vec<2>> deltaV;
    ContactState<2> state{p.x, p.v, p, 1e-3, [&](std::size_t a) { return p.F[a].determinant(); }};
    contact->apply(state, deltaV);
    CHECK(contact->pairsSearched() == 1);
    Vec<2> momentum = Vec<2>::Zero();
    double scale = 0.0;
    for (std::size_t a = 0; a < p.size(); ++a)
    {
        momentum += p.m[a] * deltaV[a];
        scale += p.m[a] * deltaV[a].norm();
        CHECK(p.v[a] == deltaV[a]);
    }
    REQUIRE(scale > 0.0);
    CHECK(momentum.norm() < 1e-13 * scale);
    // A is pushed towards -x, B towards +x.
    double pushA = 0.0;
    double pushB = 0.0;
    for (std::size_t a = 0; a < p.size(); ++a)
    {
        (p.body[a] == 0 ? pushA : pushB) += p.m[a] * deltaV[a][0];
    }
    CHECK(pushA < 0.0);
    CHECK(pushB > 0.0);
    // Particles farther than the support from the other body get nothing.
    for (std::size_t a = 0; a < p.size(); ++a)
    {
        const double toOther = p.body[a] == 0 ? 5.5 - p.x[a][0] : p.x[a][0] - 5.0;
        if (toOther > kernel->supportRadius() + 0.3)
        {
            CHECK(deltaV[a].norm() == 0.0);
        }
    }
    // Fixed particles are not kicked.
    ParticleSet<2> q = twoBlocks(0.5);
    q.fixed.assign(q.size(), 1);
    ContactState<2> fixedState{q.x, q.v, q, 1e-3, [&](std::size_t a) { return q.F[a].determinant(); }};
    contact->apply(fixedState, deltaV);
    for (const auto& dv : deltaV)
    {
        CHECK(dv.norm() == 0.0);
    }
}

TEST_CASE("repulsion costs nothing for separated bodies and a single body", "[contact]")
{
    const auto kernel = test::makeKernel("cubicSpline", 2, 1.0, 1.5);
    auto contact = repulsion(*kernel);
    ParticleSet<2> p = twoBlocks(10.0);
    std::vector<Vec<2>> deltaV;
    ContactState<2> state{p.x, p.v, p, 1e-3, [&](std::size_t a) { return p.F[a].determinant(); }};
    contact->apply(state, deltaV);
    CHECK(contact->pairsSearched() == 0);
    for (const auto& dv : deltaV)
    {
        CHECK(dv.norm() == 0.0);
    }
    // Within reach (gap 2 < support 3) but not listed in `pairs`: no search either.
    auto three = test::build<Contact<2>>("type repulsion; kappa 1e6; pairs (A C);",
                                         {kernel.get(), std::vector<std::string>{"A", "B", "C"}}, 2,
                                         Selection::withBodies({"A", "B", "C"}));
    ParticleSet<2> near = twoBlocks(1.0);
    near.bodies.push_back(BodyRange{"C", near.size(), near.size()});
    ContactState<2> nearState{near.x, near.v, near, 1e-3,
                              [&](std::size_t a) { return near.F[a].determinant(); }};
    three->apply(nearState, deltaV);
    CHECK(three->pairsSearched() == 0);
}

TEST_CASE("repulsion errors: unknown or self pairs", "[contact][errors]")
{
    const auto kernel = test::makeKernel("cubicSpline", 2, 1.0, 1.5);
    // The unknown name is reported where it was written, with the bodies and a suggestion.
    const std::string unknown =
        test::requireInputError([&] { repulsion(*kernel, "pairs (A Bee);"); }, 1, 45,
                                "no body named 'Bee' ('pairs' in 'model')");
    CHECK_THAT(unknown, Catch::Contains("Bodies (2): A, B"));
    CHECK_THAT(unknown, Catch::Contains("Did you mean 'B'?"));
    CHECK_THROWS_WITH(repulsion(*kernel, "pairs (A A);"), Catch::Contains("in contact with itself"));
    CHECK_THROWS_WITH(repulsion(*kernel, "pairs (A);"), Catch::Contains("two by two"));
}
