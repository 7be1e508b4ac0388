// Deficient supports (particles/CorrectedGradient.hpp, the gradF least-squares matrix Z): a
// particle whose neighbours no longer span every direction — a chain one particle thick, a
// particle that left its body, as granular flows make them once the reference moves — gets a
// regularised corrected gradient. Checked: along the chain f is exact for an affine motion and
// across it f = I; an isolated particle has f = I and no force; a regular cloud is untouched
// (no complement); and with a chain hanging off a block, every scheme's force is still
// −∂Π/∂x and conserves momentum. The same for gradF's joint fit, which completes its own f_a
// (docs/theory/gradF-plastic.md §G17).
#include "numerics/NumericsSupport.hpp"
#include "stabilisation/gradF/GradF.hpp"

using namespace sph;

namespace
{

const std::string kHencky = "type hencky; E 1e6; nu 0.3; rho 1000;";

// A 6 x 6 lattice (spacing 1) with a chain of `chain` particles leaving its right edge at
// mid-height, and optionally one particle far away.
std::vector<Vec<2>> blockWithChain(int chain, bool isolated)
{
    std::vector<Vec<2>> x;
    for (int j = 0; j < 6; ++j)
    {
        for (int i = 0; i < 6; ++i)
        {
            x.push_back(Vec<2>(i, j));
        }
    }
    for (int k = 1; k <= chain; ++k)
    {
        x.push_back(Vec<2>(5 + 1.0 * k, 2.5));
    }
    if (isolated)
    {
        x.push_back(Vec<2>(30.0, 30.0));
    }
    return x;
}

ReferenceConfiguration<2> referenceOf(const std::vector<Vec<2>>& x, const Kernel& kernel)
{
    ReferenceConfiguration<2> ref;
    ref.x = x;
    ref.V.assign(x.size(), 1.0);
    ref.F.assign(x.size(), Mat<2>::Identity());
    ref.rebuild(kernel, std::vector<int>(x.size(), 0), kernel.supportRadius());
    return ref;
}

Mat<2> deformationAt(const ReferenceConfiguration<2>& ref, std::size_t a, const std::vector<Vec<2>>& x)
{
    Mat<2> moment = Mat<2>::Zero();
    for (std::size_t k = ref.neighbours.begin(a) + 1; k < ref.neighbours.end(a); ++k)
    {
        const std::size_t b = ref.neighbours.indices[k];
        moment += ref.V[b] * (x[b] - x[a]) * ref.gradW(a, k).transpose();
    }
    return ref.gradient.deformation(a, moment);
}

} // namespace

TEST_CASE("a deficient support: f exact along a chain, the identity across it and alone",
          "[csph][deficientSupport]")
{
    const auto kernel = test::makeKernel("cubicSpline", 2, 1.0, 1.4); // support 2.8 spacings
    const auto points = blockWithChain(4, true);
    const ReferenceConfiguration<2> ref = referenceOf(points, *kernel);
    const std::size_t tip = 36 + 3; // the chain's last particle: neighbours only along x
    const std::size_t alone = points.size() - 1;
    REQUIRE(ref.neighbours.count(alone) == 1);
    REQUIRE(ref.gradient.deficient >= 2);
    REQUIRE(!ref.gradient.complement.empty());
    for (std::size_t a = 0; a < points.size(); ++a)
    {
        INFO("particle " << a);
        CHECK(ref.gradient.L[a].allFinite());
        CHECK((deformationAt(ref, a, points) - Mat<2>::Identity()).cwiseAbs().maxCoeff() < 1e-12);
    }
    // An affine motion x = A X + c: f t = A t along the chain (t = x), f n = n across it.
    Mat<2> A;
    A << 1.2, 0.3, -0.1, 0.9;
    std::vector<Vec<2>> x(points.size());
    for (std::size_t a = 0; a < points.size(); ++a)
    {
        x[a] = A * points[a] + Vec<2>(0.4, -0.7);
    }
    const Mat<2> f = deformationAt(ref, tip, x);
    CHECK((f.col(0) - A.col(0)).cwiseAbs().maxCoeff() < 1e-12);
    CHECK((f.col(1) - Vec<2>(0.0, 1.0)).cwiseAbs().maxCoeff() < 1e-12);
    CHECK((deformationAt(ref, alone, x) - Mat<2>::Identity()).cwiseAbs().maxCoeff() < 1e-15);
    // Inside the block nothing changed: f = A there, exactly as without regularisation.
    CHECK((deformationAt(ref, 14, x) - A).cwiseAbs().maxCoeff() < 1e-12);
    CHECK(ref.gradient.complement[14] == Mat<2>::Zero());

    // A regular lattice keeps no complement at all (f as before, to the bit).
    const ReferenceConfiguration<2> regular = referenceOf(blockWithChain(0, false), *kernel);
    CHECK(regular.gradient.deficient == 0);
    CHECK(regular.gradient.complement.empty());
}

TEST_CASE("a deficient support: forces stay -dPi/dx and conserve momentum in every scheme",
          "[csph][deficientSupport][energy]")
{
    const auto points = blockWithChain(3, true);
    for (const std::string name : {"none", "gradF", "hourglass", "vidal", "gradF fit joint"})
    {
        INFO(name);
        test::SchemeFixture<2> fixture(points, test::schemeText<2>(name), kHencky, false, 1.4,
                                       "cubicSpline", 1, true);
        REQUIRE(fixture.ref.gradient.deficient > 0);
        const auto x = test::deformCurrent<2>(fixture.ref.x, 5);
        ForceStatus status;
        const auto T = fixture.forces(x, &status);
        REQUIRE(status.ok());
        CHECK(T.back() == Vec<2>::Zero()); // the isolated particle feels nothing
        double maxForce = 0.0;
        Vec<2> total = Vec<2>::Zero();
        for (const auto& t : T)
        {
            REQUIRE(t.allFinite());
            maxForce = std::max(maxForce, t.cwiseAbs().maxCoeff());
            total += t;
        }
        CHECK(total.cwiseAbs().maxCoeff() < 1e-12 * maxForce * static_cast<double>(T.size()));
        if (name == "hourglass")
        {
            continue; // its penalty is no energy's derivative (spec §12; SchemeForceTest)
        }
        CHECK(test::largestForceError(fixture, x, T) / maxForce < 1e-6);
    }
}

TEST_CASE("a deficient support: gradF's joint fit exact along a chain, the identity across it and alone",
          "[deficientSupport][joint]")
{
    const auto points = blockWithChain(4, true);
    test::SchemeFixture<2> fixture(points, "type gradF; fit joint;", kHencky, false, 1.4,
                                   "cubicSpline", 1, true);
    const auto& gradF = dynamic_cast<const GradF<2>&>(*fixture.scheme);
    const std::size_t tip = 36 + 3;
    const std::size_t alone = points.size() - 1;
    for (std::size_t a = 0; a < points.size(); ++a)
    {
        INFO("particle " << a);
        const auto kin = gradF.kinematics(a, points, fixture.ref);
        CHECK(kin.F.allFinite());
        CHECK((kin.F - Mat<2>::Identity()).cwiseAbs().maxCoeff() < 1e-12);
    }
    Mat<2> A;
    A << 1.2, 0.3, -0.1, 0.9;
    std::vector<Vec<2>> x(points.size());
    for (std::size_t a = 0; a < points.size(); ++a)
    {
        x[a] = A * points[a] + Vec<2>(0.4, -0.7);
    }
    const Mat<2> f = gradF.kinematics(tip, x, fixture.ref).F;
    CHECK((f.col(0) - A.col(0)).cwiseAbs().maxCoeff() < 1e-12);
    CHECK((f.col(1) - Vec<2>(0.0, 1.0)).cwiseAbs().maxCoeff() < 1e-12);
    CHECK((gradF.kinematics(alone, x, fixture.ref).F - Mat<2>::Identity()).cwiseAbs().maxCoeff() <
          1e-15);
    CHECK((gradF.kinematics(14, x, fixture.ref).F - A).cwiseAbs().maxCoeff() < 1e-12);
}
