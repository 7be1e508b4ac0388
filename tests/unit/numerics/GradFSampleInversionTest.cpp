// gradF elasticState refuses a move that would invert a stress sample (docs/theory/
// gradF-plastic.md §G3, §G11): the state a sample carries across a move is rebased with its
// f_b(a) = f_a + H_a x^r_ba, and be = F Cp⁻¹ Fᵀ is positive definite whatever the sign of det F,
// so an inverted sample would carry on, in silence, as its mirror image. A step's motion so
// rough that some sample inverts while every particle's own F stays positive must stop the
// move with that sample's particle and det f_b(a); a smooth step must not.
#include "numerics/NumericsSupport.hpp"
#include "stabilisation/gradF/GradF.hpp"

using namespace sph;

namespace
{

const char* kPlastic = "type j2Plasticity; E 2.5; nu 0.3; rho 1; yieldStress 0.02; "
                       "hardeningModulus 0.2;";

// One particle of the lattice moved by `kick` (in spacings) along x: a step's motion that is
// smooth everywhere but there.
template <int D>
std::vector<Vec<D>> kicked(const std::vector<Vec<D>>& x, std::size_t particle, double kick)
{
    std::vector<Vec<D>> y(x);
    y[particle][0] += kick;
    return y;
}

struct Samples
{
    double smallest = 1e300;  // det f_b(a) over every sample
    double particles = 1e300; // det f_a over every particle
};

template <int D>
Samples determinants(test::SchemeFixture<D>& f, const std::vector<Vec<D>>& x)
{
    auto& scheme = dynamic_cast<GradF<D>&>(*f.scheme);
    Samples s;
    for (std::size_t a = 0; a < x.size(); ++a)
    {
        const auto kin = scheme.kinematics(a, x, f.ref);
        const double Jr = f.ref.F[a].determinant();
        s.particles = std::min(s.particles, kin.F.determinant() / Jr);
        for (std::size_t k = f.ref.neighbours.begin(a); k < f.ref.neighbours.end(a); ++k)
        {
            const std::size_t b = f.ref.neighbours.indices[k];
            const Mat<D> sample = kin.F + kin.G.contract(Vec<D>(f.ref.x[b] - f.ref.x[a]));
            s.smallest = std::min(s.smallest, sample.determinant() / Jr);
        }
    }
    return s;
}

template <int D>
void inversionStopsTheMove(double kick, bool inverts)
{
    INFO(D << "D, one particle kicked by " << kick << " spacings");
    test::SchemeFixture<D> f(test::schemeCloud<D>(7), "type gradF; plasticSamples elasticState;",
                             kPlastic, false, test::schemeHOverDx<D>());
    // A yielded history, then one move so that the samples carry their elastic state.
    auto x = test::deformCurrent<D>(f.ref.x, 17);
    REQUIRE(f.commit(x) > 0.0);
    REQUIRE(f.moveReference(x).ok());
    f.commit(x);
    const std::size_t centre = x.size() / 2;
    // In 3D the samples have more neighbours to fit: two neighbours kicked towards each other.
    const auto y = D == 2 ? kicked<D>(x, centre, kick)
                          : kicked<D>(kicked<D>(x, centre, kick), centre + 1, -kick);
    const Samples s = determinants<D>(f, y);
    INFO("smallest det f_b(a) " << s.smallest << ", smallest det f_a " << s.particles);
    REQUIRE(s.particles > 0.0); // every particle's own F is admissible
    REQUIRE((s.smallest <= 0.0) == inverts);
    const ForceStatus status = f.moveReference(y);
    if (!inverts)
    {
        CHECK(status.ok());
        return;
    }
    CHECK_FALSE(status.ok());
    CHECK(status.failure == FailureKind::nonPositiveJacobian);
    CHECK(status.badValue <= 0.0);
    CHECK(status.message.find("stress sample") != std::string::npos);
}

} // namespace

TEST_CASE("gradF elasticState: a move that would invert a stress sample stops with it",
          "[plasticity][gradF]")
{
    test::loadModelLibraries();
    inversionStopsTheMove<2>(0.05, false); // every sample positive: the move is made
    inversionStopsTheMove<2>(0.9, true);   // the kicked particle's neighbours' samples invert
    inversionStopsTheMove<3>(0.8, true);
}
