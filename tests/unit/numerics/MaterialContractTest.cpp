// Family contract, run on every registered material in 1D, 2D and 3D (design §6):
// P(I) = 0, Ψ(I) = 0, P = ∂Ψ/∂F by central differences, objectivity of the finite-strain
// models, agreement with linearElastic at small strain, and the wave speed against the
// principal longitudinal tangent ∂P_ii/∂F_ii.
#include "numerics/NumericsSupport.hpp"
#include "particles/FastMath.hpp"

#include <map>

using namespace sph;

namespace
{

// Parameters per model, and the linearElastic parameters it must agree with at small strain.
struct MaterialCase
{
    std::string text;
    std::string linear1D;  // 1D: E equal to the model's uniaxial modulus at F = I
    std::string linearND;  // 2D/3D: the same Lamé constants
    bool objective;
    // The time step's wave speed is a bound (materials with history: the elastic modulus at
    // the total stretch, docs/theory/plasticity.md (P2.5)) rather than the exact tangent.
    bool waveSpeedBound = false;
};

const std::map<std::string, MaterialCase>& cases()
{
    static const std::map<std::string, MaterialCase> table{
        {"linearElastic",
         {"type linearElastic; E 2; nu 0.3; rho 1;", "type linearElastic; E 2; rho 1;",
          "type linearElastic; E 2; nu 0.3; rho 1;", false}},
        {"stVenantKirchhoff",
         {"type stVenantKirchhoff; E 2; nu 0.3; rho 1;", "type linearElastic; E 2; rho 1;",
          "type linearElastic; E 2; nu 0.3; rho 1;", true}},
        // mu = 1, kappa = 5: E = 9 kappa mu/(3 kappa + mu) = 45/16, nu = 13/32; 1D (uniaxial
        // strain): kappa + 4 mu/3.
        {"neoHookean",
         {"type neoHookean; mu 1; kappa 5; rho 1;", "type linearElastic; E 6.333333333333333; rho 1;",
          "type linearElastic; E 2.8125; nu 0.40625; rho 1;", true}},
        // E 2, nu 0.3 (K = 5/3, mu = 10/13).
        {"hencky",
         {"type hencky; E 2; nu 0.3; rho 1;", "type linearElastic; E 2; rho 1;",
          "type linearElastic; E 2; nu 0.3; rho 1;", true}},
        // Yielding at strains of 1 %: the random gradients below flow plastically, so the
        // contract (P = ∂W/∂F, objectivity) is checked on the return map itself.
        {"j2Plasticity",
         {"type j2Plasticity; E 2; nu 0.3; rho 1; yieldStress 0.02; hardeningModulus 0.1;",
          "type linearElastic; E 2; rho 1;", "type linearElastic; E 2; nu 0.3; rho 1;", true, true}},
        // Associative (psi = phi) with a cut-off below the apex: then W = Psi + tau:dEp is the
        // incremental potential (docs/theory/plasticity.md (P9.4)) and P = dW/dF while
        // flowing on the cone, the cut-off or their edge (2D, 3D only).
        {"druckerPrager",
         {"type druckerPrager; E 2; nu 0.3; rho 1; frictionAngle 30; dilatancyAngle 30; "
          "cohesion 0.01; tensileStrength 0.01;",
          "", "type linearElastic; E 2; nu 0.3; rho 1;", true, true}},
    };
    return table;
}

template <int D>
Mat<D> randomGradient(std::mt19937& random, double amplitude)
{
    std::normal_distribution<double> normal;
    Mat<D> F = Mat<D>::Identity();
    for (int i = 0; i < D; ++i)
    {
        for (int j = 0; j < D; ++j)
        {
            F(i, j) += amplitude * normal(random);
        }
    }
    return F;
}

template <int D>
Mat<D> rotation(double angle)
{
    Mat<D> Q = Mat<D>::Identity();
    if constexpr (D >= 2)
    {
        Eigen::Matrix3d R = (Eigen::AngleAxisd(angle, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()))
                                .toRotationMatrix();
        if constexpr (D == 2)
        {
            Q << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
        }
        else
        {
            Q = R;
        }
    }
    return Q;
}

template <int D>
void checkMaterial(const std::string& name)
{
    const auto found = cases().find(name);
    REQUIRE(found != cases().end()); // every registered material needs a row in the table
    const MaterialCase& c = found->second;
    const auto material = test::build<Material<D>>(c.text, {}, D);
    const auto linear = test::build<Material<D>>(D == 1 ? c.linear1D : c.linearND, {}, D);
    INFO(name << " in " << D << "D");

    const Mat<D> I = Mat<D>::Identity();
    CHECK(material->stress(I).cwiseAbs().maxCoeff() < 1e-14);
    CHECK(std::abs(material->energy(I)) < 1e-14);

    std::mt19937 random(11);
    for (int trial = 0; trial < 5; ++trial)
    {
        const Mat<D> F = randomGradient<D>(random, 0.2);
        REQUIRE(F.determinant() > 0.2);
        // P = ∂Ψ/∂F
        const Mat<D> P = material->stress(F);
        Mat<D> numeric;
        const double step = 1e-6;
        for (int i = 0; i < D; ++i)
        {
            for (int j = 0; j < D; ++j)
            {
                Mat<D> Fp = F;
                Mat<D> Fm = F;
                Fp(i, j) += step;
                Fm(i, j) -= step;
                numeric(i, j) = (material->energy(Fp) - material->energy(Fm)) / (2 * step);
            }
        }
        CHECK((P - numeric).cwiseAbs().maxCoeff() < 1e-7 * std::max(1.0, P.cwiseAbs().maxCoeff()));
        // The batch agrees with the single call (to round-off: it may order the arithmetic
        // differently to vectorise).
        Mat<D> batchP;
        double batchPsi;
        material->evaluate(&F, &batchP, &batchPsi, 1, HistoryOf::particles(0));
        CHECK((batchP - P).cwiseAbs().maxCoeff() <= 1e-14 * (1.0 + P.cwiseAbs().maxCoeff()));
        CHECK(batchPsi == material->energy(F));
        // Objectivity: Ψ(QF) = Ψ(F), P(QF) = Q P(F).
        if (c.objective && D > 1)
        {
            const Mat<D> Q = rotation<D>(0.7 + trial);
            CHECK(material->energy(Q * F) == Approx(material->energy(F)).epsilon(1e-12));
            CHECK((material->stress(Q * F) - Q * P).cwiseAbs().maxCoeff() < 1e-12 * (1 + P.norm()));
        }
    }
    // Small strain: P(I + εA) agrees with linearElastic to O(ε).
    const double eps = 1e-6;
    const Mat<D> A = randomGradient<D>(random, 1.0) - I;
    const Mat<D> Ps = material->stress(I + eps * A) / eps;
    const Mat<D> Pl = linear->stress(I + eps * A) / eps;
    CHECK((Ps - Pl).cwiseAbs().maxCoeff() < 1e-4 * Pl.cwiseAbs().maxCoeff());

    // Wave speed: ρ c^2 = max_i ∂P_ii/∂F_ii at a diagonal (principal) F; at F = I the
    // small-strain P-wave modulus.
    for (const double stretch : {1.0, 1.08, 0.93})
    {
        Mat<D> F = I;
        F(0, 0) = stretch;
        if (D > 1)
        {
            F(1, 1) = 1.0 / std::sqrt(stretch);
        }
        double modulus = 0.0;
        for (int i = 0; i < D; ++i)
        {
            Mat<D> Fp = F;
            Mat<D> Fm = F;
            Fp(i, i) += 1e-6;
            Fm(i, i) -= 1e-6;
            modulus = std::max(modulus, (material->stress(Fp)(i, i) - material->stress(Fm)(i, i)) / 2e-6);
        }
        const double c = material->waveSpeed(F);
        INFO("stretch " << stretch);
        if (found->second.waveSpeedBound)
        {
            // Never below the tangent (lower while flowing plastically), and within the stress
            // term of (P2.5) of the elastic speed at the smallest stretch.
            const double exact = std::sqrt(modulus / material->density());
            const double smallest = D == 1 ? stretch : std::min(stretch, 1.0 / std::sqrt(stretch));
            CHECK(c >= exact * (1.0 - 1e-6));
            CHECK(c <= 1.3 * std::max(exact, material->waveSpeed(I) / smallest));
        }
        else if (name == "stVenantKirchhoff")
        {
            // Never below the small-strain speed (compression softens St.V-K; Δt stays safe).
            const double c0 = material->waveSpeed(I);
            CHECK(c == Approx(std::max(c0, std::sqrt(modulus / material->density()))).epsilon(1e-5));
        }
        else
        {
            CHECK(c == Approx(std::sqrt(modulus / material->density())).epsilon(1e-5));
        }
    }
}

template <int D>
void checkAllMaterials()
{
    test::loadModelLibraries();
    const auto names = Registry<Material<D>>::names();
    REQUIRE(names.size() >= 3);
    for (const std::string& name : names)
    {
        checkMaterial<D>(name);
    }
}

} // namespace

TEST_CASE("material contract holds for every registered material (1D)", "[material]")
{
    checkAllMaterials<1>();
}

TEST_CASE("material contract holds for every registered material (2D)", "[material]")
{
    checkAllMaterials<2>();
}

TEST_CASE("material contract holds for every registered material (3D)", "[material]")
{
    checkAllMaterials<3>();
}

TEST_CASE("material errors: impossible values and missing keys", "[material][errors]")
{
    CHECK_THROWS_WITH(test::build<Material<2>>("type linearElastic; E 1; rho 1;", {}, 2),
                      Catch::Contains("linearElastic in 2D needs 'nu'"));
    CHECK_THROWS_WITH(test::build<Material<2>>("type neoHookean; mu -1; kappa 1; rho 1;", {}, 2),
                      Catch::Contains("mu = -1 must lie in (0, inf)"));
    CHECK_THROWS_WITH(test::build<Material<3>>("type neoHookean; mu 1; kappa 1;", {}, 3),
                      Catch::Contains("missing required key 'rho'"));
    CHECK_THROWS_WITH(test::build<Material<2>>("type stVenantKirchhoff; E 1; nu 0.5; rho 1;", {}, 2),
                      Catch::Contains("nu = 0.5 must lie in (-1, 0.5)"));
}

TEST_CASE("the inline inverse cube root is accurate to a few ulp", "[material]")
{
    double worst = 0.0;
    for (double x = 1e-3; x < 1e3; x *= 1.0137)
    {
        const double exact = 1.0 / std::cbrt(x);
        worst = std::max(worst, std::abs(inverseCubeRoot(x) - exact) / exact);
    }
    CHECK(worst < 2e-15);
}
