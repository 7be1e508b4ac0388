// An initial stress held as an initial elastic strain (docs/theory/plasticity.md §P10,
// Material::startFromStress): at F = I the point's Cauchy stress is the given one, zz included
// (plane strain), its energy is the elastic energy of that strain, and loading from there adds
// the elastic response to it; a stress outside the yield surface is refused and changes
// nothing; materials without history cannot; the at-rest coefficients are Jaky's and ν/(1 − ν).
#include "materials/LogarithmicElasticity.hpp"
#include "numerics/NumericsSupport.hpp"

#include <numbers>

using namespace sph;

namespace
{

// E 7.2e6, nu 0.2: K = 4e6, μ = 3e6.
const std::string dp = "type druckerPrager; E 7.2e6; nu 0.2; rho 2000; frictionAngle 30; cohesion 1e3;";
const std::string j2 = "type j2Plasticity; E 7.2e6; nu 0.2; rho 2000; yieldStress 5e4;";

// A stress inside both yield surfaces (σ in Pa; compression negative), not along the axes.
Eigen::Matrix3d insideStress()
{
    Eigen::Matrix3d sigma;
    sigma << -3.0e4, 4.0e3, 0.0, //
        4.0e3, -5.0e4, 0.0,      //
        0.0, 0.0, -2.5e4;
    return sigma;
}

// τ of the point's committed Cp⁻¹ at F = I, zz included: be = Cp⁻¹, εe = ½ ln be, τ = Hencky.
template <int D>
Eigen::Matrix3d stressOfState(const test::MaterialPoint<D>& point)
{
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> be(point.inversePlastic());
    const Eigen::Vector3d eps = 0.5 * be.eigenvalues().array().log().matrix();
    const HenckyLaw law(4e6, 3e6);
    return be.eigenvectors() * law.kirchhoff(eps).asDiagonal() * be.eigenvectors().transpose();
}

template <int D>
void checkStartsFromStress(const std::string& text)
{
    INFO(text << " " << D << "D");
    test::MaterialPoint<D> point(text);
    Eigen::Matrix3d sigma = insideStress();
    if (D == 3)
    {
        sigma(0, 2) = sigma(2, 0) = 2.0e3;
    }
    REQUIRE(point.material->startFromStress(0, sigma) == Material<D>::InitialStress::set);
    const Mat<D> I = Mat<D>::Identity();
    const Mat<D> P = point.stress(I);
    CHECK((P - sigma.topLeftCorner<D, D>()).cwiseAbs().maxCoeff() < 1e-9 * sigma.norm());
    CHECK((stressOfState(point) - sigma).cwiseAbs().maxCoeff() < 1e-9 * sigma.norm());
    CHECK(point.alpha() == 0.0);
    // The energy is the elastic energy of the initial strain: ½ σ : C⁻¹ : σ.
    const double K = 4e6;
    const double mu = 3e6;
    const double mean = sigma.trace() / 3.0;
    const Eigen::Matrix3d deviator = sigma - mean * Eigen::Matrix3d::Identity();
    const double elastic = deviator.squaredNorm() / (4.0 * mu) + mean * mean / (2.0 * K);
    CHECK(point.energy(I) == Approx(elastic).epsilon(1e-3)); // Hencky vs small strain: O(ε)
    // A small elastic increment from there: P(I + e) − σ is the small-strain response C : e
    // to first order (the pre-strain is ~1e-2 of it, so 2 % agreement, not round-off).
    Mat<D> e = Mat<D>::Zero();
    e(0, 0) = 1e-5;
    e(D - 1, 0) = e(0, D - 1) = 0.5e-5;
    const Mat<D> dP = point.stress(I + e) - P;
    const double lambda = K - 2.0 * mu / 3.0;
    const Mat<D> expected = lambda * e.trace() * I + 2.0 * mu * e;
    CHECK((dP - expected).cwiseAbs().maxCoeff() < 2e-2 * expected.cwiseAbs().maxCoeff());
    // A stress beyond the yield surface: refused, the state left as it was.
    const Eigen::Matrix3d before = point.inversePlastic();
    Eigen::Matrix3d beyond = Eigen::Matrix3d::Zero();
    beyond(0, 0) = -1e6;
    CHECK(point.material->startFromStress(0, beyond) == Material<D>::InitialStress::outsideYieldSurface);
    CHECK(point.inversePlastic() == before);
}

} // namespace

TEST_CASE("an initial stress is held as an initial elastic strain (druckerPrager, j2Plasticity)",
          "[plasticity][initialStress]")
{
    checkStartsFromStress<2>(dp);
    checkStartsFromStress<3>(dp);
    checkStartsFromStress<2>(j2);
    checkStartsFromStress<3>(j2);
}

TEST_CASE("an initial stress in 1D: the bar's j2Plasticity", "[plasticity][initialStress]")
{
    test::MaterialPoint<1> point("type j2Plasticity; E 7.2e6; rho 2000; yieldStress 5e4;");
    Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
    sigma(0, 0) = -3e4;
    REQUIRE(point.material->startFromStress(0, sigma) == Material<1>::InitialStress::set);
    CHECK(point.stress(Mat<1>::Identity())(0, 0) == Approx(-3e4).epsilon(1e-12));
}

TEST_CASE("only materials with history start from a stress, the at-rest coefficients",
          "[plasticity][initialStress]")
{
    test::MaterialPoint<2> hencky("type hencky; E 7.2e6; nu 0.2; rho 2000;");
    CHECK(hencky.material->startFromStress(0, insideStress()) == Material<2>::InitialStress::notSupported);
    CHECK(std::isnan(hencky.material->atRestCoefficient()));
    test::MaterialPoint<2> soil(dp);
    CHECK(soil.material->atRestCoefficient() == Approx(1.0 - std::sin(30.0 * std::numbers::pi / 180.0)));
    test::MaterialPoint<3> metal(j2);
    CHECK(metal.material->atRestCoefficient() == Approx(0.2 / 0.8));
}
