// druckerPrager against hand-computed returns and the properties of docs/theory/plasticity.md
// §P9: the smooth-cone return (P9.3) and the apex return written out, a cohesionless material
// pulled into tension, ψ = 0 without plastic volume change, ψ = φ associative, the tension
// cut-off, Mohr–Coulomb in steady plane-strain flow with the planeStrain matching,
// objectivity, elastic unloading, and the input checks. The material is driven through the
// Material interface as the solver drives it (test::MaterialPoint).
#include "numerics/NumericsSupport.hpp"

#include <Eigen/Eigenvalues>

#include <iomanip>
#include <numbers>
#include <sstream>
#include <tuple>

using namespace sph;

namespace
{

// E 7.2e6, nu 0.2: K = E/(3(1 − 2ν)) = 4e6, μ = E/(2(1 + ν)) = 3e6 (round numbers by hand).
constexpr double K = 4e6;
constexpr double mu = 3e6;
constexpr double cohesion = 1e4;
const double degree = std::numbers::pi / 180.0;

std::string dpText(double phi, double psi, double c = cohesion, const std::string& extra = "")
{
    return "type druckerPrager; E 7.2e6; nu 0.2; rho 2000; frictionAngle " + formatNumber(phi) +
           "; dilatancyAngle " + formatNumber(psi) + "; cohesion " + formatNumber(c) + "; " + extra;
}

// The principal Kirchhoff stresses of a virgin 3D point at principal log strains eps (the
// trial strain: F = diag(exp εᵢ) gives be = diag(exp 2εᵢ)).
Eigen::Vector3d returnedStress(test::MaterialPoint<3>& point, const Eigen::Vector3d& eps)
{
    const Mat<3> F = eps.array().exp().matrix().asDiagonal();
    const Mat<3> tau = point.kirchhoff(F);
    REQUIRE((tau - Mat<3>(tau.diagonal().asDiagonal())).cwiseAbs().maxCoeff() <
            1e-9 * tau.norm() + 1e-12);
    return tau.diagonal();
}

double pressure(const Eigen::Vector3d& tau)
{
    return tau.sum() / 3.0;
}
double rootJ2(const Eigen::Vector3d& tau)
{
    return (tau - Eigen::Vector3d::Constant(pressure(tau))).norm() / std::sqrt(2.0);
}

// η, ξ of the planeStrain matching, written out: η(φ) = 3 tan φ/√(9 + 12 tan² φ).
double etaOf(double angle)
{
    const double t = std::tan(angle * degree);
    return 3 * t / std::sqrt(9 + 12 * t * t);
}
double xiOf(double angle)
{
    const double t = std::tan(angle * degree);
    return 3 / std::sqrt(9 + 12 * t * t);
}

// A random 3D gradient near the identity.
Mat<3> randomGradient(std::mt19937& random, double amplitude)
{
    std::normal_distribution<double> normal;
    Mat<3> F = Mat<3>::Identity();
    for (int i = 0; i < 3; ++i)
    {
        for (int j = 0; j < 3; ++j)
        {
            F(i, j) += amplitude * normal(random);
        }
    }
    return F;
}

} // namespace

// φ = 30°, ψ = 10°, c = 1e4 Pa, K = 4e6, μ = 3e6. By hand: η = 3 tan 30°/√13 = 0.48038446,
// ξ = 3/√13 = 0.83205029, η̄ = 3 tan 10°/√(9 + 12 tan² 10°) = 0.172782013.
// Trial ε = (1, −2, −8)e-3: εv = −9e-3, p_tr = K εv = −36000; dev ε = (4, 1, −5)e-3,
// √J2_tr = √2 μ |dev ε| = √2·3e6·√42e-3 = 27495.454; Φ_tr = 27495.454 − 0.48038446·36000
// − 0.83205029·1e4 = 1881.1106 > 0; Δγ = Φ_tr/(μ + K η η̄) = 1881.1106/3332008.9
// = 5.6455779e-4; √J2 = √J2_tr − μΔγ = 25801.781 (≥ 0: on the cone), p = p_tr − K η̄ Δγ
// = −36390.182 (≤ σt).
TEST_CASE("druckerPrager: the smooth-cone return against a hand-computed case",
          "[plasticity][druckerPrager]")
{
    CHECK(etaOf(30) == Approx(0.48038446).epsilon(1e-8));
    CHECK(xiOf(30) == Approx(0.83205029).epsilon(1e-8));
    CHECK(etaOf(10) == Approx(0.172782013).epsilon(1e-8));
    test::MaterialPoint<3> point(dpText(30, 10));
    const Eigen::Vector3d tau = returnedStress(point, {1e-3, -2e-3, -8e-3});
    CHECK(pressure(tau) == Approx(-36390.182).epsilon(1e-8));
    CHECK(rootJ2(tau) == Approx(25801.781).epsilon(1e-8));
    // On the cone to round-off, and s along s_tr (the return is radial in the deviatoric plane).
    const double phi = rootJ2(tau) + etaOf(30) * pressure(tau) - xiOf(30) * cohesion;
    CHECK(std::abs(phi) < 1e-10 * cohesion);
    const Eigen::Vector3d s = tau - Eigen::Vector3d::Constant(pressure(tau));
    const Eigen::Vector3d sTrial(4, 1, -5);
    CHECK((s.normalized() - sTrial.normalized()).norm() < 1e-12);
    // α += √(2/3)|dev Δεp| = √(2/3)·μΔγ/(√2 μ)... = Δγ/√3 on the cone.
    point.commit(Eigen::Vector3d(1e-3, -2e-3, -8e-3).array().exp().matrix().asDiagonal());
    CHECK(point.alpha() == Approx(5.6455779e-4 / std::sqrt(3.0)).epsilon(1e-7));
}

// The same material, trial ε = (5, 4, 3)e-3: εv = 0.012 beyond εt = σt/K = 4.3301270e-3 (σt
// the default, the apex ξ c/η = c cot 30° = 17320.508), so p = σt (P9.5); √J2_tr =
// √2·3e6·√2e-3 = 6000, Φ_tr = 6000 + η σt − ξ c = 6000 (η σt = ξ c), Δγ = Φ_tr/μ = 2e-3:
// s = 0 (the apex), εv = 0.012 − η̄ Δγ = 0.011654436 ≥ εt (the capped branch holds). Δεp: all
// of dev ε, |dev ε| = √2e-3, so α = √(2/3)√2e-3 = 1.1547005e-3; the plastic work τ:Δεp =
// p η̄ Δγ = 17320.508·0.172782013·2e-3 = 5.9853445 J/m³ (the volumetric strain beyond εt is
// open voids, not plastic flow: no work), which the commit dissipates.
TEST_CASE("druckerPrager: the apex return, and a cohesionless material in tension",
          "[plasticity][druckerPrager]")
{
    SECTION("c > 0: hand-computed apex")
    {
        test::MaterialPoint<3> point(dpText(30, 10));
        const Eigen::Vector3d eps(5e-3, 4e-3, 3e-3);
        const Eigen::Vector3d tau = returnedStress(point, eps);
        CHECK((tau - Eigen::Vector3d::Constant(17320.508075688773)).cwiseAbs().maxCoeff() <
              1e-9 * 17320.5);
        CHECK(point.commit(eps.array().exp().matrix().asDiagonal()) ==
              Approx(5.9853445).epsilon(1e-7));
        CHECK(point.alpha() == Approx(1.1547005e-3).epsilon(1e-7));
    }
    SECTION("c = 0: pulled apart the stress is zero; pressed together, the voids close first")
    {
        for (const double psi : {0.0, 20.0})
        {
            INFO("psi " << psi);
            test::MaterialPoint<3> point(dpText(30, psi, 0.0));
            const Eigen::Vector3d eps(1e-3, 2e-3, -0.5e-3); // εv = 2.5e-3 > εt = 0
            const Mat<3> F = eps.array().exp().matrix().asDiagonal();
            CHECK(returnedStress(point, eps).cwiseAbs().maxCoeff() < 1e-12 * K * 1e-3);
            // It flows (α grows) but dissipates nothing: the plastic work is done at zero stress.
            CHECK(std::abs(point.commit(F)) < 1e-20 * K);
            CHECK(point.alpha() > 1e-3);
            // The opened state carries no stress at F, nor when pressed a little: open voids.
            CHECK(std::abs(point.energy(F)) < 1e-20 * K);
            CHECK(point.kirchhoff(F * std::exp(-1e-4)).cwiseAbs().maxCoeff() < 1e-12 * K * 1e-3);
            if (psi == 0.0)
            {
                // ψ = 0: the cone flowed deviatorically, the voids are the whole εv = 2.5e-3;
                // pressed by 2.8e-3 they close and the last 3e-4 is elastic compression.
                const Mat<3> tau = point.kirchhoff(F * std::exp(-2.8e-3 / 3.0));
                CHECK((tau - Mat<3>::Identity() * (-3e-4 * K)).cwiseAbs().maxCoeff() <
                      1e-9 * 3e-4 * K);
            }
        }
    }
}

// The wave-speed bound (docs/theory/plasticity.md (P2.7)): where the voids are open the pressure
// does not change with εv, so the bound drops K, and at the apex of a cohesionless cone (every
// admissible state stress-free) it drops μ too; a closed point keeps the elastic (P2.5). Through
// maxWaveSpeed, the time step's call, from the committed state of an opened point.
TEST_CASE("druckerPrager: the wave-speed bound of an open point (P2.7)",
          "[plasticity][druckerPrager]")
{
    const double rho = 2000.0;
    const Mat<3> opened = Eigen::Vector3d(1e-3, 2e-3, -0.5e-3).array().exp().matrix().asDiagonal();
    const Mat<3> squeezed =
        Eigen::Vector3d(-1e-3, -2e-3, -0.5e-3).array().exp().matrix().asDiagonal();
    const double closedC = std::sqrt((K + 4 * mu / 3) / rho);
    SECTION("c = 0: no stress and no stiffness while open; the elastic bound once closed")
    {
        test::MaterialPoint<3> point(dpText(30, 0, 0.0));
        CHECK(point.material->maxWaveSpeed(&opened, 1, 0) < 1e-6 * closedC); // τ at round-off
        point.commit(opened);
        CHECK(point.material->maxWaveSpeed(&opened, 1, 0) < 1e-6 * closedC); // τ at round-off
        // Pressed beyond the voids (εv = 2.5e-3 of them): the elastic M and the stress are back.
        const Mat<3> closed = opened * std::exp(-4e-3 / 3.0);
        const double c = point.material->maxWaveSpeed(&closed, 1, 0);
        CHECK(c > closedC);
        CHECK(c < 1.01 * closedC / std::exp(-4e-3 / 3.0 - 0.5e-3));
    }
    SECTION("c > 0: beyond the tension cut-off the shear modulus alone (and |τ| = σt)")
    {
        test::MaterialPoint<3> point(dpText(30, 0, cohesion, "tensileStrength 1000;"));
        const Mat<3> far = Eigen::Vector3d(1e-2, 1e-2, 1e-2).array().exp().matrix().asDiagonal();
        const double c = point.material->maxWaveSpeed(&far, 1, 0);
        const double lambda = std::exp(1e-2);
        CHECK(c == Approx(std::sqrt((4 * mu / 3 + 1000.0) / rho) / lambda).epsilon(1e-9));
    }
    SECTION("a closed, compressed point: (P2.5) unchanged")
    {
        test::MaterialPoint<3> point(dpText(30, 0, 0.0));
        const double c = point.material->maxWaveSpeed(&squeezed, 1, 0);
        const Mat<3> tau = point.kirchhoff(squeezed);
        CHECK(c == Approx(std::sqrt((K + 4 * mu / 3 + tau.cwiseAbs().maxCoeff()) / rho) /
                          std::exp(-2e-3))
                       .epsilon(1e-12));
    }
}

// ψ = 0: the cone's flow is deviatoric, εv unchanged, det Cp⁻¹ = exp(−2 tr εp) stays 1;
// ψ = φ: Δεp = εtr − ε is parallel to ∂Φ/∂τ = s/(2√J2) + η/3 1 at the returned τ. Both on the
// smooth cone (compressed, sheared states; the cut-off's flow is volumetric by design).
TEST_CASE("druckerPrager: psi = 0 keeps the volume, psi = phi flows along the normal",
          "[plasticity][druckerPrager]")
{
    std::mt19937 random(5);
    int volumeKept = 0;
    int normal = 0;
    const double apex = cohesion / std::tan(35 * degree);
    for (int trial = 0; trial < 40; ++trial)
    {
        const Mat<3> F = randomGradient(random, 0.02) * std::exp(-0.01);
        {
            test::MaterialPoint<3> point(dpText(35, 0));
            const double p = point.kirchhoff(F).trace() / 3;
            if (point.commit(F) > 0.0 && p < 0.99 * apex)
            {
                ++volumeKept;
                CHECK(std::abs(point.inversePlastic().determinant() - 1.0) < 1e-14);
            }
        }
        {
            test::MaterialPoint<3> point(dpText(35, 35));
            const Mat<3> tau = point.kirchhoff(F);
            Eigen::SelfAdjointEigenSolver<Mat<3>> trialStrain(F * F.transpose());
            const Mat<3> epsTrial = 0.5 * trialStrain.eigenvectors() *
                                    trialStrain.eigenvalues().array().log().matrix().asDiagonal() *
                                    trialStrain.eigenvectors().transpose();
            const double p = tau.trace() / 3;
            const Mat<3> s = tau - p * Mat<3>::Identity();
            const Mat<3> eps = s / (2 * mu) + p / (3 * K) * Mat<3>::Identity(); // 𝔻⁻¹ τ
            const Mat<3> plastic = epsTrial - eps;
            if (plastic.norm() < 1e-9 || p > 0.99 * apex)
            {
                continue;
            }
            ++normal;
            const double j2 = std::sqrt(0.5 * (s.array() * s.array()).sum());
            const Mat<3> n = s / (2 * j2) + etaOf(35) / 3 * Mat<3>::Identity();
            const Mat<3> across =
                plastic - (plastic.array() * n.array()).sum() / n.squaredNorm() * n;
            CHECK(across.norm() < 1e-8 * plastic.norm());
        }
    }
    CHECK(volumeKept > 10);
    CHECK(normal > 10);
}

// σt below the apex: p never exceeds σt, whatever the path; both the cut-off plane
// (s unchanged) and its edge with the cone are reached.
TEST_CASE("druckerPrager: the tension cut-off", "[plasticity][druckerPrager]")
{
    const double sigmaT = 5000.0; // apex: 17320.5
    std::mt19937 random(3);
    int atCutOff = 0;
    for (int trial = 0; trial < 50; ++trial)
    {
        test::MaterialPoint<3> point(dpText(30, 10, cohesion, "tensileStrength 5000;"));
        for (int step = 1; step <= 5; ++step)
        {
            const Mat<3> F = randomGradient(random, 0.004) * std::exp(0.001 * step);
            const Mat<3> tau = point.kirchhoff(F);
            CHECK(tau.trace() / 3 <= sigmaT * (1 + 1e-12));
            atCutOff += std::abs(tau.trace() / 3 - sigmaT) < 1e-9 * sigmaT ? 1 : 0;
            point.commit(F);
        }
    }
    CHECK(atCutOff > 20);
    SECTION("plane: the shear is kept")
    {
        test::MaterialPoint<3> point(dpText(30, 10, cohesion, "tensileStrength 5000;"));
        const Eigen::Vector3d eps(3.0e-3, 2.9e-3, 3.1e-3); // √J2_tr = √2 μ √2e-4 = 600 < ξc − ησt
        const Eigen::Vector3d tau = returnedStress(point, eps);
        CHECK(pressure(tau) == Approx(sigmaT).epsilon(1e-12));
        CHECK(rootJ2(tau) == Approx(600.0).epsilon(1e-9));
    }
    SECTION("edge: p = σt and on the cone")
    {
        test::MaterialPoint<3> point(dpText(30, 10, cohesion, "tensileStrength 5000;"));
        const Eigen::Vector3d tau = returnedStress(point, {5e-3, 3e-3, 1e-3});
        CHECK(pressure(tau) == Approx(sigmaT).epsilon(1e-12));
        CHECK(rootJ2(tau) == Approx(xiOf(30) * cohesion - etaOf(30) * sigmaT).epsilon(1e-10));
    }
}

// Plane strain: in steady plastic flow ε̇p_zz = 0, and with the matching for the flow's ψ the
// in-plane principal stresses satisfy Mohr–Coulomb of angle φ exactly (§P9, (P9.6)):
// (σ1 − σ3)/2 = c cos φ − (σ1 + σ3)/2 sin φ. After an elastic pre-compression, the path
// stretches y and compresses x at the ratio of Mohr–Coulomb's own plane-strain flow with
// dilatancy ψ, ε̇y : ε̇x = (1 + sin ψ) : −(1 − sin ψ), so that a steady state (constant stress,
// all the strain rate plastic) exists; the stress approaches it geometrically as plastic strain
// accumulates (the elastic zz strain of first yield relaxes through the flow's zz component).
// Measured at the end of the path: |residual| ≈ 1e-10 Pa for stresses of order 1e4–1e5 Pa
// (round-off: the transient has died out); 1e-9 c = 1e-5 Pa leaves room for the last digits of
// the transient and platform differences, and is 1e-9 of what a wrong matching gives (the
// outer cone at 30° gives t = 1.31 c − 0.76 m instead of 0.87 c − 0.5 m: 0.44 c at m = 0).
namespace
{
double planeStrainFlowResidual(double phi, double psi, const std::string& matching)
{
    test::MaterialPoint<2> point(dpText(phi, psi, cohesion, "coneMatching " + matching + ";"));
    const double sinPsi = std::sin(psi * degree);
    Mat<2> F = Mat<2>::Identity();
    double residual = 0.0;
    for (int step = 1; step <= 2000; ++step)
    {
        F(0, 0) = std::exp(-2e-3 - 1e-4 * (1 - sinPsi) * step);
        F(1, 1) = std::exp(-2e-3 + 1e-4 * (1 + sinPsi) * step);
        point.commit(F);
        const Mat<2> tau = point.kirchhoff(F);
        const double s1 = std::max(tau(0, 0), tau(1, 1));
        const double s3 = std::min(tau(0, 0), tau(1, 1));
        residual = (s1 - s3) / 2 -
                   (cohesion * std::cos(phi * degree) - (s1 + s3) / 2 * std::sin(phi * degree));
    }
    REQUIRE(point.alpha() > 0.05);
    return residual;
}
} // namespace

TEST_CASE("druckerPrager: planeStrain matching reproduces Mohr-Coulomb in plane strain",
          "[plasticity][druckerPrager]")
{
    for (const double phi : {20.0, 30.0, 40.0})
    {
        INFO("phi " << phi);
        CHECK(std::abs(planeStrainFlowResidual(phi, phi, "planeStrain")) < 1e-9 * cohesion);
        // planeStrainFlow is planeStrain when the flow is associative, and exact at any ψ
        for (const double psi : {0.0, phi / 2, phi})
        {
            INFO("psi " << psi);
            CHECK(std::abs(planeStrainFlowResidual(phi, psi, "planeStrainFlow")) < 1e-9 * cohesion);
        }
        // planeStrain with ψ = 0 is a cone of the wrong width for the flow it has: by (P9.6)
        // its in-plane friction is asin(η) (28.7° at φ = 30°, 19.6° at 20°, 37.5° at 40°) and
        // its cohesion ξ c, so at the path's end, where the in-plane mean stress m is several
        // c, the residual is (sin φ − η) |m| + (ξ − cos φ) c: 0.03–0.3 c at these φ.
        CHECK(std::abs(planeStrainFlowResidual(phi, 0.0, "planeStrain")) > 0.01 * cohesion);
    }
}

// Objectivity: a rotation of the current configuration rotates P and leaves W, from a
// committed plastic state; and an unloading step from a yielding state has the elastic slope.
// The outer cone passes through Mohr–Coulomb's compression meridian (σ1 = σ2 > σ3, tension
// positive), the inner cone through its extension meridian (σ1 > σ2 = σ3) (§P9; de Souza Neto
// et al. 2008 §8.2.4). A trial state on a meridian returns along it (the return keeps the
// deviatoric direction), so the returned principal stresses satisfy Mohr–Coulomb exactly,
// (σ1 − σ3)/2 = c cos φ − (σ1 + σ3)/2 sin φ; the other cone does not (by hand, at φ = 30°
// and σ3 = −10 c: Mohr–Coulomb's compression point lies 1.3 c outside the inner cone).
TEST_CASE("druckerPrager: outer and inner cones are Mohr-Coulomb on the compression and extension "
          "meridians",
          "[plasticity][druckerPrager]")
{
    const auto mohrCoulombResidual = [](const Eigen::Vector3d& tau, double phi)
    {
        const double s1 = tau.maxCoeff();
        const double s3 = tau.minCoeff();
        return (s1 - s3) / 2.0 - (cohesion * std::cos(phi) - (s1 + s3) / 2.0 * std::sin(phi));
    };
    for (const double phi : {20.0, 30.0, 40.0})
    {
        INFO("phi " << phi);
        // Compression: two equal larger strains, one much more compressive (yields at these φ).
        const Eigen::Vector3d compression(1e-2, 1e-2, -6e-2);
        // Extension: one larger strain, two equal more compressive ones.
        const Eigen::Vector3d extension(2e-2, -3e-2, -3e-2);
        for (const auto& [matching, onMeridian, offMeridian] :
             {std::tuple{"outer", compression, extension},
              std::tuple{"inner", extension, compression}})
        {
            INFO(matching);
            test::MaterialPoint<3> on(
                dpText(phi, 0, cohesion, std::string("coneMatching ") + matching + ";"));
            const Eigen::Vector3d tau = returnedStress(on, onMeridian);
            REQUIRE(tau.sum() / 3.0 < 0.0); // on the cone, not at the apex
            CHECK(std::abs(mohrCoulombResidual(tau, phi * degree)) <
                  1e-9 * std::abs(tau.minCoeff()));
            test::MaterialPoint<3> off(
                dpText(phi, 0, cohesion, std::string("coneMatching ") + matching + ";"));
            CHECK(std::abs(mohrCoulombResidual(returnedStress(off, offMeridian), phi * degree)) >
                  0.01 * cohesion);
        }
    }
}

TEST_CASE("druckerPrager: objectivity and elastic unloading", "[plasticity][druckerPrager]")
{
    SECTION("rotation")
    {
        test::MaterialPoint<3> point(dpText(30, 10));
        std::mt19937 random(7);
        const Mat<3> F1 = randomGradient(random, 0.01) * std::exp(-0.002);
        REQUIRE(point.commit(F1) > 0.0);
        const Mat<3> F = randomGradient(random, 0.01) * std::exp(-0.002);
        const Mat<3> Q =
            Eigen::AngleAxisd(0.9, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
        const Mat<3> P = point.stress(F);
        CHECK((point.stress(Q * F) - Q * P).cwiseAbs().maxCoeff() < 1e-12 * P.norm());
        CHECK(point.energy(Q * F) == Approx(point.energy(F)).epsilon(1e-12));
    }
    SECTION("uniaxial strain: load past yield, then unload with slope K + 4μ/3")
    {
        test::MaterialPoint<3> point(dpText(30, 0));
        Mat<3> F = Mat<3>::Identity();
        double dissipated = 0.0;
        for (int step = 1; step <= 40; ++step)
        {
            F(0, 0) = std::exp(-2.5e-4 * step);
            dissipated += point.commit(F);
        }
        REQUIRE(dissipated > 0.0);
        const double eps = std::log(F(0, 0));
        const double tau0 = point.kirchhoff(F)(0, 0);
        Mat<3> unloaded = F;
        unloaded(0, 0) = std::exp(eps + 1e-5);
        const double slope = (point.kirchhoff(unloaded)(0, 0) - tau0) / 1e-5;
        CHECK(slope == Approx(K + 4 * mu / 3).epsilon(1e-9));
        // and loading further is softer (the cone's plastic modulus)
        Mat<3> loaded = F;
        loaded(0, 0) = std::exp(eps - 1e-5);
        CHECK((tau0 - point.kirchhoff(loaded)(0, 0)) / 1e-5 < 0.9 * (K + 4 * mu / 3));
    }
}

TEST_CASE("druckerPrager: input checks", "[plasticity][druckerPrager][errors]")
{
    CHECK_THROWS_WITH(test::build<Material<2>>(dpText(30, 31), {}, 2),
                      Catch::Contains("dilatancyAngle 31 exceeds frictionAngle 30") &&
                          Catch::Contains("[0, 30]"));
    CHECK_THROWS_WITH(test::build<Material<3>>(dpText(30, 0, 1e4, "tensileStrength 2e4;"), {}, 3),
                      Catch::Contains("exceeds the cone's apex pressure"));
    CHECK_THROWS_WITH(test::build<Material<2>>(dpText(0, 0), {}, 2),
                      Catch::Contains("frictionAngle = 0 must lie in (0, 90)"));
    CHECK_THROWS_WITH(test::build<Material<2>>(dpText(30, 0, 1e4, "coneMatching outside;"), {}, 2),
                      Catch::Contains("inner") && Catch::Contains("outer") &&
                          Catch::Contains("planeStrainFlow"));
    CHECK_THROWS_WITH(
        test::build<Material<1>>("type druckerPrager; E 1; rho 1; frictionAngle 30;", {}, 1),
        Catch::Contains("2D, 3D"));
    // Every matching has the same apex pressure c cot φ; the outer cone is the widest.
    for (const char* matching : {"planeStrain", "planeStrainFlow", "outer", "inner"})
    {
        test::MaterialPoint<3> point(
            dpText(30, 0, cohesion, std::string("coneMatching ") + matching + ";"));
        const Eigen::Vector3d tau = returnedStress(point, {5e-3, 4e-3, 3e-3});
        CHECK(pressure(tau) == Approx(cohesion * std::sqrt(3.0)).epsilon(1e-12));
    }
}

// strengthReduction F (docs/theory/geotechnics.md (E2.1)) is the material with c/F, tan φ/F,
// ψ capped at the reduced φ and tensileStrength/F, and Jaky's K0 of the reduced angle.
TEST_CASE("druckerPrager: strengthReduction is the material with the reduced strength",
          "[plasticity][druckerPrager]")
{
    const double F = 1.6;
    const double phiF = std::atan(std::tan(30 * degree) / F) / degree; // 19.84°
    std::mt19937 random(11);
    struct Case
    {
        double psi;      // of the soil
        double psiF;     // of the reduced soil
        std::string cut; // its cut-off, as given and reduced
        std::string cutF;
    };
    for (const Case& c : {Case{0.0, 0.0, "", ""}, Case{10.0, 10.0, "", ""},
                          Case{30.0, phiF, "", ""}, // associative stays associative
                          Case{10.0, 10.0, "tensileStrength 8000;", "tensileStrength 5000;"}})
    {
        INFO("psi " << c.psi << " " << c.cut);
        test::MaterialPoint<3> reduced(dpText(30, c.psi, cohesion,
                                              "coneMatching planeStrainFlow; strengthReduction 1.6; " + c.cut));
        // (the angles to 17 digits: dpText's formatNumber would round them)
        std::ostringstream text;
        text << std::setprecision(17) << "type druckerPrager; E 7.2e6; nu 0.2; rho 2000; "
             << "frictionAngle " << phiF << "; dilatancyAngle " << c.psiF << "; cohesion "
             << cohesion / F << "; coneMatching planeStrainFlow; " << c.cutF;
        test::MaterialPoint<3> direct(text.str());
        double largest = 0.0;
        for (int step = 1; step <= 20; ++step)
        {
            const Mat<3> F3 = randomGradient(random, 0.004) * std::exp(0.0005 * step);
            const Mat<3> a = reduced.kirchhoff(F3);
            const Mat<3> b = direct.kirchhoff(F3);
            largest = std::max(largest, b.norm());
            CHECK((a - b).norm() <= 1e-10 * b.norm());
            reduced.commit(F3);
            direct.commit(F3);
        }
        CHECK(reduced.alpha() > 0.0); // it yielded
        CHECK(reduced.alpha() == Approx(direct.alpha()).epsilon(1e-9));
    }
    // Jaky's K0 of the reduced soil, inside its cone; the elasticity is the soil's.
    const auto soil = test::build<Material<2>>(dpText(30, 0, cohesion, "strengthReduction 1.6;"), {}, 2);
    CHECK(soil->atRestCoefficient() == Approx(1 - std::sin(phiF * degree)).epsilon(1e-12));
    // A reduction makes a weaker material: from a virgin point (ψ = 0: the return keeps the
    // pressure) the reduced one returns to a smaller shear stress at the same pressure.
    for (int trial = 0; trial < 20; ++trial)
    {
        test::MaterialPoint<3> strong(dpText(30, 0, cohesion, ""));
        test::MaterialPoint<3> weak(dpText(30, 0, cohesion, "strengthReduction 1.6;"));
        const Mat<3> F3 = randomGradient(random, 0.01);
        const Eigen::Vector3d s = Eigen::SelfAdjointEigenSolver<Mat<3>>(strong.kirchhoff(F3)).eigenvalues();
        const Eigen::Vector3d w = Eigen::SelfAdjointEigenSolver<Mat<3>>(weak.kirchhoff(F3)).eigenvalues();
        CHECK(pressure(w) == Approx(pressure(s)).epsilon(1e-12));
        CHECK(rootJ2(w) <= rootJ2(s) * (1 + 1e-12));
    }
    // The cut-off is checked as given (the apex c cot φ = 17320.5 Pa), whatever F is.
    CHECK_THROWS_WITH(test::build<Material<3>>(dpText(30, 0, 1e4, "tensileStrength 2e4; "
                                                                   "strengthReduction 2;"),
                                               {}, 3),
                      Catch::Contains("exceeds the cone's apex pressure"));
}
