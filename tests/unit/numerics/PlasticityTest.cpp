// j2Plasticity against the closed forms of docs/theory/plasticity.md: uniaxial strain and
// uniaxial stress load-unload-reload (elastic, hardening and unloading slopes, reverse yield),
// the return on the yield surface, det Fp = 1, objectivity, simple shear, P = ∂W/∂F from a
// plastic state, and no yielding = `hencky` to the bit. The material is driven through the
// Material interface as the solver drives it: trial evaluations, then one commit per level.
#include "numerics/NumericsSupport.hpp"

#include <Eigen/Eigenvalues>

using namespace sph;

namespace
{

constexpr double E = 200e9;
constexpr double nu = 0.3;
constexpr double sigmaY0 = 200e6;
constexpr double hardening = 2e9;
const double mu = E / (2 * (1 + nu));
const double bulk = E / (3 * (1 - 2 * nu));

std::string j2Text(double H = hardening, double yield = sigmaY0)
{
    return "type j2Plasticity; E " + std::to_string(E) + "; nu " + std::to_string(nu) +
           "; rho 8000; yieldStress " + std::to_string(yield) + "; hardeningModulus " +
           std::to_string(H) + ";";
}

// test::MaterialPoint with the von Mises stress of its committed state.
template <int D>
struct MaterialPoint : test::MaterialPoint<D>
{
    using test::MaterialPoint<D>::MaterialPoint;
    using test::MaterialPoint<D>::inversePlastic;
    // The von Mises stress of the committed state at F, from be = F Cp⁻¹ Fᵀ and Hencky's law
    // written out here independently of the material's code.
    double vonMises(const Mat<D>& F) const
    {
        Eigen::Matrix3d F3 = Eigen::Matrix3d::Identity();
        F3.topLeftCorner<D, D>() = F;
        const Eigen::Matrix3d be = F3 * inversePlastic() * F3.transpose();
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(be);
        const Eigen::Vector3d eps = 0.5 * solver.eigenvalues().array().log();
        const Eigen::Vector3d dev = eps - Eigen::Vector3d::Constant(eps.sum() / 3);
        return std::sqrt(1.5) * 2 * mu * dev.norm();
    }
};

template <int D>
Mat<D> stretchX(double lambda, double lateral = 1.0)
{
    Mat<D> F = Mat<D>::Identity() * lateral;
    F(0, 0) = lambda;
    return F;
}

// The path of the load-unload-reload tests, in logarithmic strain along x.
std::vector<double> cyclicPath()
{
    std::vector<double> path;
    for (int i = 1; i <= 20; ++i) path.push_back(0.001 * i);          // load to 2 %
    for (int i = 1; i <= 40; ++i) path.push_back(0.02 - 0.001 * i);   // unload, reverse to -2 %
    for (int i = 1; i <= 15; ++i) path.push_back(-0.02 + 0.002 * i);  // reload to +1 %
    return path;
}

// Uniaxial strain (lateral stretches 1), docs/theory/plasticity.md §P5: a scalar model on the
// deviatoric variable, s = 2μ (e − g), |s| ≤ σy0 + H α, dα = (2/3)|dg|, τ_xx = K e + (2/3) s.
struct UniaxialStrainReference
{
    double g = 0.0;
    double alpha = 0.0;
    double step(double e)
    {
        const double sTrial = 2 * mu * (e - g);
        const double f = std::abs(sTrial) - (sigmaY0 + hardening * alpha);
        if (f > 0)
        {
            const double dAlpha = f / (3 * mu + hardening);
            g += std::copysign(1.5 * dAlpha, sTrial);
            alpha += dAlpha;
        }
        return bulk * e + (2.0 / 3.0) * 2 * mu * (e - g);
    }
};

// Uniaxial stress: τ = E (e − εp), |τ| ≤ σy0 + H α (§P6, and 3D with free lateral stretches).
struct UniaxialStressReference
{
    double plastic = 0.0;
    double alpha = 0.0;
    double step(double e)
    {
        const double tauTrial = E * (e - plastic);
        const double f = std::abs(tauTrial) - (sigmaY0 + hardening * alpha);
        if (f > 0)
        {
            const double dAlpha = f / (E + hardening);
            plastic += std::copysign(dAlpha, tauTrial);
            alpha += dAlpha;
        }
        return E * (e - plastic);
    }
};

// Slopes dτ/de of a path, one per step.
std::vector<double> slopes(const std::vector<double>& path, const std::vector<double>& tau)
{
    std::vector<double> result;
    double previousE = 0.0;
    double previousTau = 0.0;
    for (std::size_t i = 0; i < path.size(); ++i)
    {
        result.push_back((tau[i] - previousTau) / (path[i] - previousE));
        previousE = path[i];
        previousTau = tau[i];
    }
    return result;
}

template <int D>
void uniaxialStrain()
{
    MaterialPoint<D> point(j2Text());
    UniaxialStrainReference reference;
    const std::vector<double> path = cyclicPath();
    std::vector<double> tau;
    bool reversed = false;
    for (const double e : path)
    {
        const Mat<D> F = stretchX<D>(std::exp(e));
        tau.push_back(point.kirchhoff(F)(0, 0));
        const double expected = reference.step(e);
        CHECK(tau.back() == Approx(expected).epsilon(1e-10).margin(1e-9 * sigmaY0));
        const double before = point.alpha();
        point.commit(F);
        CHECK(point.alpha() == Approx(reference.alpha).epsilon(1e-10).margin(1e-15));
        if (point.alpha() > before)
        {
            // The return lands on the yield surface.
            CHECK(std::abs(point.vonMises(F) - (sigmaY0 + hardening * point.alpha())) <=
                  1e-10 * sigmaY0);
            if (e < 0.02 && !reversed && before > 0.0 && tau.size() > 20)
            {
                // Reverse yield: the first flowing step of the unloading branch has the
                // deviatoric stress s_xx = τ_xx - K e = -(2/3)(σy0 + H α).
                reversed = true;
                CHECK(tau.back() - bulk * e ==
                      Approx(-(2.0 / 3.0) * (sigmaY0 + hardening * point.alpha())).epsilon(1e-9));
            }
        }
        CHECK(std::abs(point.inversePlastic().determinant() - 1.0) < 1e-13); // det Fp = 1
    }
    // The slopes of the closed form: elastic M, hardening K + 4μH/(3(3μ + H)), unloading M,
    // and the reverse yield at q = σy0 + H α_max (the first step of the unloading branch that
    // is not elastic).
    const auto k = slopes(path, tau);
    const double M = bulk + 4 * mu / 3;
    const double hardeningSlope = bulk + 4 * mu * hardening / (3 * (3 * mu + hardening));
    CHECK(k[0] == Approx(M).epsilon(1e-9));                  // elastic
    CHECK(k[15] == Approx(hardeningSlope).epsilon(1e-9));    // hardening (well past yield)
    CHECK(k[21] == Approx(M).epsilon(1e-9));                 // unloading
    CHECK(k[45] == Approx(hardeningSlope).epsilon(1e-9));    // reverse flow
    CHECK(k[60] == Approx(M).epsilon(1e-9));                 // reloading
    CHECK(reversed);
}

TEST_CASE("j2Plasticity in uniaxial strain: load, unload, reverse, reload against the closed form",
          "[plasticity]")
{
    uniaxialStrain<2>();
    uniaxialStrain<3>();
}

// 3D uniaxial stress: the lateral stretch is solved each step so that τ_yy = τ_zz = 0.
TEST_CASE("j2Plasticity in uniaxial stress (3D, and the 1D bar) against the closed form",
          "[plasticity]")
{
    MaterialPoint<3> point(j2Text());
    MaterialPoint<1> bar(j2Text());
    UniaxialStressReference reference;
    const std::vector<double> path = cyclicPath();
    std::vector<double> tau3;
    std::vector<double> tau1;
    double lateral = 1.0;
    for (const double e : path)
    {
        const double lambda = std::exp(e);
        for (int iteration = 0; iteration < 30; ++iteration)
        {
            const double residual = point.kirchhoff(stretchX<3>(lambda, lateral))(1, 1);
            const double h = 1e-7;
            const double slope = (point.kirchhoff(stretchX<3>(lambda, lateral + h))(1, 1) -
                                  point.kirchhoff(stretchX<3>(lambda, lateral - h))(1, 1)) /
                                 (2 * h);
            lateral -= residual / slope;
            if (std::abs(residual) < 1e-12 * sigmaY0)
            {
                break;
            }
        }
        const Mat<3> F = stretchX<3>(lambda, lateral);
        REQUIRE(std::abs(point.kirchhoff(F)(1, 1)) < 1e-10 * sigmaY0);
        const double expected = reference.step(e);
        tau3.push_back(point.kirchhoff(F)(0, 0));
        tau1.push_back(bar.kirchhoff(stretchX<1>(lambda))(0, 0));
        CHECK(tau3.back() == Approx(expected).epsilon(1e-9).margin(1e-8 * sigmaY0));
        CHECK(tau1.back() == Approx(expected).epsilon(1e-12).margin(1e-12 * sigmaY0));
        point.commit(F);
        bar.commit(stretchX<1>(lambda));
        CHECK(point.alpha() == Approx(reference.alpha).epsilon(1e-9).margin(1e-14));
        CHECK(bar.alpha() == Approx(reference.alpha).epsilon(1e-12).margin(1e-15));
        CHECK(std::abs(point.inversePlastic().determinant() - 1.0) < 1e-13);
    }
    const auto k = slopes(path, tau3);
    CHECK(k[0] == Approx(E).epsilon(1e-8));
    CHECK(k[15] == Approx(E * hardening / (E + hardening)).epsilon(1e-7));
    CHECK(k[21] == Approx(E).epsilon(1e-8));
    CHECK(k[60] == Approx(E).epsilon(1e-8));
    // Reverse yield at τ = -(σy0 + H α_max): the last elastic unloading step is above it, the
    // first reverse-flowing one on it.
    UniaxialStressReference replay;
    double peakAlpha = 0.0;
    for (std::size_t i = 0; i < path.size(); ++i)
    {
        const double before = replay.alpha;
        replay.step(path[i]);
        if (i < 20)
        {
            peakAlpha = replay.alpha;
        }
        else if (i < 60 && replay.alpha > before && before == peakAlpha)
        {
            // the first reverse-flowing step
            CHECK(tau3[i] == Approx(-(sigmaY0 + hardening * replay.alpha)).epsilon(1e-9));
            CHECK(tau3[i - 1] > -(sigmaY0 + hardening * peakAlpha));
        }
    }
}

TEST_CASE("j2Plasticity: objectivity of the return and of the committed state", "[plasticity]")
{
    MaterialPoint<3> point(j2Text());
    MaterialPoint<3> rotated(j2Text());
    const Mat<3> Q = Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
    std::mt19937 random(5);
    std::normal_distribution<double> normal;
    Mat<3> F = Mat<3>::Identity();
    for (int step = 0; step < 40; ++step)
    {
        Mat<3> increment = Mat<3>::Identity();
        for (int i = 0; i < 3; ++i)
        {
            for (int j = 0; j < 3; ++j)
            {
                increment(i, j) += 0.002 * normal(random);
            }
        }
        F = increment * F;
        const Mat<3> P = point.stress(F);
        CHECK((rotated.stress(Q * F) - Q * P).cwiseAbs().maxCoeff() < 1e-9 * P.norm());
        CHECK(rotated.energy(Q * F) == Approx(point.energy(F)).epsilon(1e-11));
        point.commit(F);
        rotated.commit(Q * F);
        // Cp⁻¹ lives in the initial configuration: a rotation of the current one leaves it alone.
        CHECK((rotated.inversePlastic() - point.inversePlastic()).cwiseAbs().maxCoeff() < 1e-11);
    }
    CHECK(point.alpha() > 0.01); // the path did flow plastically
    CHECK(std::abs(point.inversePlastic().determinant() - 1.0) < 1e-13);
}

TEST_CASE("j2Plasticity in simple shear: on the yield surface, det Fp = 1, perfect plasticity "
          "saturates",
          "[plasticity]")
{
    MaterialPoint<2> point(j2Text(0.0));
    for (int step = 1; step <= 250; ++step)
    {
        Mat<2> F = Mat<2>::Identity();
        F(0, 1) = 0.002 * step; // γ up to 0.5
        const Mat<2> tau = point.kirchhoff(F);
        const double before = point.alpha();
        point.commit(F);
        if (point.alpha() > before)
        {
            CHECK(std::abs(point.vonMises(F) - sigmaY0) <= 1e-10 * sigmaY0);
        }
        CHECK(std::abs(point.inversePlastic().determinant() - 1.0) < 1e-13);
        if (step == 250)
        {
            // Perfectly plastic: the shear stress is bounded by σy0/√3 and close to it once
            // the normal stresses of the rotating axes are small.
            CHECK(tau(0, 1) <= sigmaY0 / std::sqrt(3.0) * (1 + 1e-12));
            CHECK(tau(0, 1) > 0.95 * sigmaY0 / std::sqrt(3.0));
            // γ - (plastic shear): α ≈ γ/√3 of the plastic part of the shear.
            CHECK(point.alpha() == Approx(0.5 / std::sqrt(3.0)).epsilon(0.03));
        }
    }
}

template <int D>
void derivativeOfIncrementalPotential()
{
    MaterialPoint<D> point(j2Text());
    // A plastic history first: stretch along x by 1 %, committed in five steps.
    for (int step = 1; step <= 5; ++step)
    {
        point.commit(stretchX<D>(std::exp(0.002 * step)));
    }
    REQUIRE(point.alpha() > 0.0);
    std::mt19937 random(3);
    std::normal_distribution<double> normal;
    for (int trial = 0; trial < 4; ++trial)
    {
        Mat<D> F = stretchX<D>(std::exp(0.012));
        for (int i = 0; i < D; ++i)
        {
            for (int j = 0; j < D; ++j)
            {
                F(i, j) += 0.004 * normal(random);
            }
        }
        const Mat<D> P = point.stress(F);
        Mat<D> numeric;
        const double h = 1e-7;
        for (int i = 0; i < D; ++i)
        {
            for (int j = 0; j < D; ++j)
            {
                Mat<D> Fp = F;
                Mat<D> Fm = F;
                Fp(i, j) += h;
                Fm(i, j) -= h;
                numeric(i, j) = (point.energy(Fp) - point.energy(Fm)) / (2 * h);
            }
        }
        INFO(D << "D, trial " << trial);
        CHECK((P - numeric).cwiseAbs().maxCoeff() < 1e-6 * P.cwiseAbs().maxCoeff());
    }
}

TEST_CASE("j2Plasticity: the stress is the derivative of the incremental potential W from a "
          "plastic state (P4.2)",
          "[plasticity]")
{
    derivativeOfIncrementalPotential<1>();
    derivativeOfIncrementalPotential<2>();
    derivativeOfIncrementalPotential<3>();
}

template <int D>
void noYieldIsHencky()
{
    MaterialPoint<D> point(j2Text(hardening, 1e30));
    const auto hencky = test::build<Material<D>>("type hencky; E " + std::to_string(E) + "; nu " +
                                                     std::to_string(nu) + "; rho 8000;",
                                                 {}, D);
    std::mt19937 random(7);
    std::normal_distribution<double> normal;
    for (int trial = 0; trial < 20; ++trial)
    {
        Mat<D> F = Mat<D>::Identity();
        for (int i = 0; i < D; ++i)
        {
            for (int j = 0; j < D; ++j)
            {
                F(i, j) += 0.1 * normal(random);
            }
        }
        Mat<D> P;
        double psi;
        hencky->evaluate(&F, &P, &psi, 1, HistoryOf::particles(0));
        // To round-off, not to the bit: j2Plasticity takes the trial strains of
        // be = F Cp⁻¹ Fᵀ (its own, 2D's zz component apart) and P = τ F⁻ᵀ along its own path.
        INFO(D << "D, trial " << trial);
        CHECK((point.stress(F) - P).cwiseAbs().maxCoeff() <= 1e-13 * P.cwiseAbs().maxCoeff());
        CHECK(std::abs(point.energy(F) - psi) <= 1e-13 * std::abs(psi));
        CHECK(point.commit(F) == 0.0);
    }
    CHECK(point.alpha() == 0.0);
}

TEST_CASE("j2Plasticity without yielding is hencky to round-off, commit dissipates nothing",
          "[plasticity]")
{
    noYieldIsHencky<1>();
    noYieldIsHencky<2>();
    noYieldIsHencky<3>();
}

TEST_CASE("j2Plasticity: dissipation of a commit is sigmaY0 times the plastic strain increment",
          "[plasticity]")
{
    MaterialPoint<2> point(j2Text());
    double dissipated = 0.0;
    double previousAlpha = 0.0;
    for (int step = 1; step <= 10; ++step)
    {
        const double increment = point.commit(stretchX<2>(std::exp(0.002 * step)));
        CHECK(increment == Approx(sigmaY0 * (point.alpha() - previousAlpha)).margin(1e-6));
        previousAlpha = point.alpha();
        dissipated += increment;
    }
    CHECK(dissipated > 0.0);
}

TEST_CASE("j2Plasticity: impossible values are input errors naming the valid range",
          "[plasticity][errors]")
{
    CHECK_THROWS_WITH(test::build<Material<2>>(j2Text(-3.1 * mu), {}, 2),
                      Catch::Contains("hardeningModulus") && Catch::Contains("below the limit"));
    CHECK_NOTHROW(test::build<Material<2>>(j2Text(-2.9 * mu), {}, 2));
    CHECK_THROWS_WITH(test::build<Material<1>>(j2Text(-1.1 * E), {}, 1),
                      Catch::Contains("(-E)"));
    CHECK_THROWS_WITH(test::build<Material<3>>(j2Text(0.0, 0.0), {}, 3),
                      Catch::Contains("yieldStress"));
}

} // namespace

// The linearised correction of the gradient-of-F scheme's evaluation 2 (§P7): P ≈ P_tr + dP +
// A : ΔF. Its error shrinks with |ΔF|² (A is the tangent of dP = P − P_tr; halving ΔF quarters
// the error), from a state that has already flowed; without flow the correction is zero.
template <int D>
void linearisedCorrection()
{
    INFO(D << "D");
    MaterialPoint<D> point(j2Text());
    point.commit(stretchX<D>(1.004));
    const Mat<D> F = stretchX<D>(1.006);
    const PlasticCorrection<D> c = point.material->plasticCorrection(F, 0);
    REQUIRE(c.flowing);
    CHECK(c.dP.norm() > 0.0);
    Mat<D> direction = Mat<D>::Zero();
    for (int i = 0; i < D; ++i)
    {
        for (int j = 0; j < D; ++j)
        {
            direction(i, j) = 0.3 + 0.1 * i - 0.2 * j + (i == j ? 0.5 : 0.0);
        }
    }
    const auto error = [&](double scale)
    {
        const Mat<D> dF = 1e-4 * scale * direction;
        Mat<D> exact;
        Mat<D> trial;
        double psi;
        const Mat<D> Fb = F + dF;
        point.material->evaluate(&Fb, &exact, &psi, 1, HistoryOf::particles(0));
        point.material->evaluate(&Fb, &trial, &psi, 1, HistoryOf::trialOf(0));
        Eigen::Matrix<double, D * D, 1> dFv;
        for (int i = 0; i < D * D; ++i)
        {
            dFv[i] = dF(i / D, i % D);
        }
        const Eigen::Matrix<double, D * D, 1> dPv = c.A * dFv;
        Mat<D> linear = trial + c.dP;
        for (int i = 0; i < D * D; ++i)
        {
            linear(i / D, i % D) += dPv[i];
        }
        return (exact - linear).norm();
    };
    const double coarse = error(1.0);
    const double fine = error(0.5);
    CHECK(coarse > 0.0);
    CHECK(fine / coarse == Approx(0.25).margin(0.05));
    // Elastic unloading: no correction.
    CHECK_FALSE(point.material->plasticCorrection(stretchX<D>(1.002), 0).flowing);
}

TEST_CASE("j2Plasticity: the linearised return correction is second-order accurate",
          "[plasticity]")
{
    linearisedCorrection<1>();
    linearisedCorrection<2>();
    linearisedCorrection<3>();
}

namespace
{

// Drives a point as the solver does (force evaluation, time step, commit at the same F), and
// a twin that is only committed: the memo of the return (ReturnMemo) must change nothing.
template <int D>
void memoChangesNothing()
{
    MaterialPoint<D> memo(j2Text());
    MaterialPoint<D> fresh(j2Text());
    // Built for a scheme that never evaluates particles (gradF): no memo fields, the same results.
    MaterialPoint<D> noMemo(j2Text(), false);
    CHECK(memo.fields.find("returnMemoF") != nullptr);
    CHECK(noMemo.fields.find("returnMemoF") == nullptr);
    for (int step = 1; step <= 12; ++step)
    {
        Mat<D> F = stretchX<D>(std::exp(0.002 * step), std::exp(-0.0007 * step));
        F(0, 1) = 0.001 * step; // not coaxial with the committed Cp⁻¹
        const Mat<D> P = memo.stress(F);
        CHECK(noMemo.stress(F) == P); // (fresh is never evaluated: nothing in its memo)
        const double cMemo = memo.material->maxWaveSpeed(&F, 1, 0);
        const double cFresh = fresh.material->maxWaveSpeed(&F, 1, 0);
        CHECK(cMemo == cFresh);
        CHECK(noMemo.material->maxWaveSpeed(&F, 1, 0) == cFresh);
        const double dMemo = memo.commit(F);
        const double dFresh = fresh.commit(F);
        CHECK(dMemo == dFresh);
        CHECK(noMemo.commit(F) == dFresh);
        CHECK(memo.alpha() == fresh.alpha());
        CHECK(memo.inversePlastic() == fresh.inversePlastic());
        CHECK(noMemo.inversePlastic() == fresh.inversePlastic());
    }
    CHECK(memo.alpha() > 0.0); // the path yields

    // A commit at another F than the evaluation's recomputes the return.
    const Mat<D> F1 = stretchX<D>(1.03);
    const Mat<D> F2 = stretchX<D>(1.035);
    memo.stress(F1);
    CHECK(memo.commit(F2) == fresh.commit(F2));
    CHECK(memo.inversePlastic() == fresh.inversePlastic());

    // A committed state changed behind the material's back (as a restart or a migration
    // writes the fields) is not the one the memo saw: the return is computed again.
    const Mat<D> F3 = stretchX<D>(1.045);
    memo.stress(F3);
    for (MaterialPoint<D>* point : {&memo, &fresh})
    {
        const double alpha = 0.5 * point->alpha();
        point->fields.find("equivalentPlasticStrain")->array->set(0, &alpha);
    }
    CHECK(memo.material->maxWaveSpeed(&F3, 1, 0) == fresh.material->maxWaveSpeed(&F3, 1, 0));
    CHECK(memo.commit(F3) == fresh.commit(F3));
    CHECK(memo.alpha() == fresh.alpha());
}

} // namespace

TEST_CASE("j2Plasticity: the time step and the commit reuse the force evaluation's return, "
          "bit for bit, and never a stale one",
          "[plasticity][memo]")
{
    memoChangesNothing<2>();
    memoChangesNothing<3>();
}
