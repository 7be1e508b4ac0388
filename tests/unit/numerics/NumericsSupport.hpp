#pragma once
// Fixtures for the numerical tests: models built by name through the registry (the way the
// solver builds them), point clouds, and the deformed reference configuration of spec §7
// (non-trivial F^r and K = ∂F^r/∂x^r) for updated-Lagrangian checks.

#include "core/DictionaryParser.hpp"
#include "formulations/Formulation.hpp"
#include "kernels/Kernel.hpp"
#include "materials/Material.hpp"
#include "particles/ReferenceConfiguration.hpp"
#include "stabilisation/Stabilisation.hpp"
#include "support/TestSupport.hpp"

#include <Eigen/Dense>

#include <random>

namespace sph::test
{

// Builds model `Base` from dictionary text such as "type neoHookean; mu 1; kappa 5; rho 1;".
template <class Base>
std::unique_ptr<Base> build(const std::string& text, const typename Base::Args& args, int dim,
                            const Selection& selection = {})
{
    loadModelLibraries();
    const auto dict = DictionaryParser::parseString("model { " + text + " }\n", "test");
    return selectModel<Base>(dict->find("model")->dict(), args, dim, selection);
}

inline std::unique_ptr<Kernel> makeKernel(const std::string& name, int dim, double spacing,
                                          double hOverDx)
{
    return build<Kernel>("type " + name + "; hOverDx " + std::to_string(hOverDx) + ";",
                         Kernel::Args{dim, spacing}, dim);
}

// A lattice of n^D points with spacing 1, each moved by up to ±perturbation.
template <int D>
std::vector<Vec<D>> lattice(int n, double perturbation, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::vector<Vec<D>> points;
    std::array<int, D> index{};
    while (true)
    {
        Vec<D> p;
        for (int d = 0; d < D; ++d)
        {
            p[d] = index[static_cast<std::size_t>(d)] + perturbation * uniform(random);
        }
        points.push_back(p);
        int d = 0;
        while (d < D && index[static_cast<std::size_t>(d)] == n - 1)
        {
            index[static_cast<std::size_t>(d)] = 0;
            ++d;
        }
        if (d == D)
        {
            break;
        }
        ++index[static_cast<std::size_t>(d)];
    }
    return points;
}

// The reference map of spec §7: x^r = B X + 0.3 (sin(k1·X) e1 + cos(k2·X) e2), with its
// analytic F^r and K = ∇_X F^r (F^r)^{-1}.
template <int D>
struct DeformedReference
{
    Mat<D> B;
    Vec<D> k1;
    Vec<D> k2;
    Vec<D> e1;
    Vec<D> e2;
    double amplitude = 0.3;

    explicit DeformedReference(unsigned seed)
    {
        std::mt19937 random(seed);
        std::normal_distribution<double> normal;
        const double k1v[3] = {0.5, 0.3, 0.2};
        const double k2v[3] = {0.4, -0.6, 0.25};
        for (int d = 0; d < D; ++d)
        {
            k1[d] = k1v[d];
            k2[d] = k2v[d];
        }
        e1 = Vec<D>::Unit(0);
        e2 = Vec<D>::Unit(std::min(1, D - 1));
        B = Mat<D>::Identity();
        for (int i = 0; i < D; ++i)
        {
            for (int j = 0; j < D; ++j)
            {
                B(i, j) += 0.1 * normal(random);
            }
        }
    }
    Vec<D> map(const Vec<D>& X) const
    {
        return B * X + amplitude * (std::sin(k1.dot(X)) * e1 + std::cos(k2.dot(X)) * e2);
    }
    Mat<D> gradient(const Vec<D>& X) const
    {
        return B + amplitude * (std::cos(k1.dot(X)) * e1 * k1.transpose() -
                                std::sin(k2.dot(X)) * e2 * k2.transpose());
    }
    // K_mjk = (∇_X F^r)_mjs (F^r)^{-1}_sk
    Tensor3<D> K(const Vec<D>& X) const
    {
        Tensor3<D> gradXF = Tensor3<D>::zero();
        for (int s = 0; s < D; ++s)
        {
            gradXF.slice[static_cast<std::size_t>(s)] =
                amplitude * (-std::sin(k1.dot(X)) * k1[s] * e1 * k1.transpose() -
                             std::cos(k2.dot(X)) * k2[s] * e2 * k2.transpose());
        }
        const Mat<D> inverse = gradient(X).inverse();
        Tensor3<D> result = Tensor3<D>::zero();
        for (int k = 0; k < D; ++k)
        {
            for (int s = 0; s < D; ++s)
            {
                result.slice[static_cast<std::size_t>(k)] +=
                    gradXF.slice[static_cast<std::size_t>(s)] * inverse(s, k);
            }
        }
        return result;
    }
};

// One body of particles with a scheme, a material and a reference configuration.
template <int D>
struct SchemeFixture
{
    ParticleFields<D> fields; // a material's history (plastic models), one entry per point
    std::unique_ptr<Kernel> kernel;
    std::unique_ptr<Material<D>> material;
    std::unique_ptr<Stabilisation<D>> scheme;
    std::vector<const Material<D>*> materials;
    std::vector<BodyRange> bodies;
    std::vector<int> body;
    std::vector<double> V0;
    std::vector<Vec<D>> X;
    ReferenceConfiguration<D> ref;

    // updated: use the deformed reference configuration of spec §7 (else x^r = X).
    // referenceMoves: Stabilisation::Args' (false: as a total-Lagrangian run builds the scheme).
    SchemeFixture(const std::vector<Vec<D>>& points, const std::string& schemeText,
                  const std::string& materialText, bool updated, double hOverDx = 1.4,
                  const std::string& kernelName = "cubicSpline", unsigned seed = 1,
                  bool deficientSupports = false, bool referenceMoves = true)
        : X(points)
    {
        const std::size_t n = points.size();
        V0.assign(n, 1.0);
        body.assign(n, 0);
        bodies = {BodyRange{"body", 0, n}};
        fields.setSize(n);
        material = build<Material<D>>(materialText, {&fields, bodies[0], nullptr}, D);
        materials = {material.get()};
        double spacing = 1.0;
        ref.x = points;
        ref.V = V0;
        ref.F.assign(n, Mat<D>::Identity());
        if (updated)
        {
            const DeformedReference<D> map(seed);
            spacing = std::pow(std::abs(map.B.determinant()), 1.0 / D);
            ref.K.resize(n);
            for (std::size_t a = 0; a < n; ++a)
            {
                ref.x[a] = map.map(points[a]);
                ref.F[a] = map.gradient(points[a]);
                ref.V[a] = V0[a] * ref.F[a].determinant();
                ref.K[a] = map.K(points[a]);
            }
        }
        kernel = makeKernel(kernelName, D, spacing, hOverDx);
        scheme = build<Stabilisation<D>>(schemeText, {kernel.get(), nullptr, referenceMoves}, D);
        if (!scheme->referenceNeeds(*kernel).gradientOfF)
        {
            ref.K.clear();
        }
        // deficientSupports: a cloud with particles whose neighbours do not span every
        // direction (singular M or Z), regularised as after a reference move.
        const long singular = ref.rebuild(*kernel, body, scheme->referenceNeeds(*kernel).searchRadius);
        const ForceStatus prepared = scheme->prepare(ref);
        if (!deficientSupports)
        {
            REQUIRE(singular < 0);
            REQUIRE(prepared.ok());
        }
        if (material->hasHistory())
        {
            scheme->declareHistory(materials, fields);
        }
    }

    ForceInput<D> input(const std::vector<Vec<D>>& x) const
    {
        return ForceInput<D>{x, V0, body, bodies, materials, ref};
    }
    std::vector<Vec<D>> forces(const std::vector<Vec<D>>& x, ForceStatus* status = nullptr)
    {
        std::vector<Vec<D>> T;
        std::vector<Mat<D>> F;
        std::vector<Mat<D>> P;
        ForceOutput<D> out{T, F, P};
        const ForceStatus result = scheme->computeForces(input(x), out, false);
        if (status)
        {
            *status = result;
        }
        return T;
    }
    double energy(const std::vector<Vec<D>>& x) { return scheme->energy(input(x)); }
    // Commits the history at positions x (as the solver does once per level: a force
    // evaluation there, then the scheme's commit); returns the dissipated energy.
    double commit(const std::vector<Vec<D>>& x)
    {
        std::vector<Vec<D>> T;
        std::vector<Mat<D>> F;
        std::vector<Mat<D>> P;
        ForceOutput<D> out{T, F, P};
        REQUIRE(scheme->computeForces(input(x), out, false).ok());
        std::vector<Material<D>*> withHistory{material->hasHistory() ? material.get() : nullptr};
        return scheme->commitHistory({F, V0, bodies, withHistory});
    }
    // Moves the reference configuration to x as the solver's ReferenceManager does
    // (updated Lagrangian): the scheme carries its history across, F^r, K, x^r, V^r and what
    // depends on them are rebuilt. Needs a force evaluation since the last change of the list.
    ForceStatus moveReference(const std::vector<Vec<D>>& x)
    {
        const bool carriesK = scheme->referenceNeeds(*kernel).gradientOfF;
        if (carriesK && ref.K.size() != x.size())
        {
            ref.K.assign(x.size(), Tensor3<D>::zero());
        }
        scheme->moveHistory(x, ref, body, {material.get()});
        const ForceStatus status = scheme->referenceUpdate(x, ref, ref.F, carriesK ? &ref.K : nullptr);
        if (!status.ok())
        {
            return status;
        }
        ref.x = x;
        for (std::size_t a = 0; a < x.size(); ++a)
        {
            ref.V[a] = V0[a] * ref.F[a].determinant();
        }
        ref.updateStep += 1;
        ref.rebuild(*kernel, body, scheme->referenceNeeds(*kernel).searchRadius, true);
        return scheme->prepare(ref);
    }
};

// The largest component of any vector of `T` (forces: the scale of a tolerance).
template <int D>
double largestComponent(const std::vector<Vec<D>>& T)
{
    double value = 0.0;
    for (const auto& t : T)
    {
        value = std::max(value, t.cwiseAbs().maxCoeff());
    }
    return value;
}

// A non-affine current configuration: x = (I + 0.15 R) x^r + 0.05 sin(x^r·w) + 0.03 noise.
template <int D>
std::vector<Vec<D>> deformCurrent(const std::vector<Vec<D>>& xr, unsigned seed)
{
    std::mt19937 random(seed);
    std::normal_distribution<double> normal;
    Mat<D> A = Mat<D>::Identity();
    for (int i = 0; i < D; ++i)
    {
        for (int j = 0; j < D; ++j)
        {
            A(i, j) += 0.15 * normal(random);
        }
    }
    Vec<D> w;
    for (int d = 0; d < D; ++d)
    {
        w[d] = 0.3 + 0.4 * d / std::max(1, D - 1);
    }
    std::vector<Vec<D>> x(xr.size());
    for (std::size_t a = 0; a < xr.size(); ++a)
    {
        x[a] = A * xr[a] + Vec<D>::Constant(0.05 * std::sin(xr[a].dot(w)));
        for (int d = 0; d < D; ++d)
        {
            x[a][d] += 0.03 * normal(random);
        }
    }
    return x;
}

// The scheme of that name with test coefficients (vidal's shift, hourglass's alpha).
template <int D>
std::string schemeText(const std::string& name)
{
    if (name == "vidal")
    {
        return D == 1 ? "type vidal; beta (0.2);"
                      : (D == 2 ? "type vidal; beta (0.2 -0.1);" : "type vidal; beta (0.2 -0.1 0.15);");
    }
    if (name == "hourglass")
    {
        return "type hourglass; alpha 20;";
    }
    if (name == "gradF fit joint")
    {
        return "type gradF; fit joint;";
    }
    return "type " + name + ";";
}

// The perturbed lattices every scheme is checked on, and their kernel sizes.
template <int D>
std::vector<Vec<D>> schemeCloud(int n2D = 8)
{
    if constexpr (D == 1)
    {
        return lattice<1>(12, 0.2, 5);
    }
    else if constexpr (D == 2)
    {
        return lattice<2>(n2D, 0.2, 5);
    }
    else
    {
        return lattice<3>(4, 0.15, 5);
    }
}

template <int D>
double schemeHOverDx()
{
    return D == 3 ? 1.6 : 1.4;
}

// The largest component of T − (−∂Π/∂x), Π = energy(x) by central differences (step in units
// of x) at every particle and direction: how far forces are from the energy's gradient.
template <int D, class Energy>
double largestGradientError(const Energy& energy, const std::vector<Vec<D>>& x,
                            const std::vector<Vec<D>>& T, double step = 1e-6)
{
    double error = 0.0;
    for (std::size_t c = 0; c < x.size(); ++c)
    {
        for (int i = 0; i < D; ++i)
        {
            auto xp = x;
            auto xm = x;
            xp[c][i] += step;
            xm[c][i] -= step;
            const double numeric = -(energy(xp) - energy(xm)) / (2 * step);
            error = std::max(error, std::abs(T[c][i] - numeric));
        }
    }
    return error;
}

// The same for a scheme's force and energy.
template <int D>
double largestForceError(SchemeFixture<D>& fixture, const std::vector<Vec<D>>& x,
                         const std::vector<Vec<D>>& T, double step = 1e-6)
{
    return largestGradientError<D>([&](const std::vector<Vec<D>>& y) { return fixture.energy(y); },
                                   x, T, step);
}

// One material point driven like a particle of the solver: trial evaluations from its
// committed state, one commit per level, and its history fields read back.
template <int D>
struct MaterialPoint
{
    ParticleFields<D> fields;
    std::unique_ptr<Material<D>> material;

    // particleEvaluations: Material::Args' (false: as gradF builds it, no memo of returns).
    explicit MaterialPoint(const std::string& text, bool particleEvaluations = true)
    {
        fields.setSize(1);
        material = test::build<Material<D>>(
            text, {&fields, BodyRange{"point", 0, 1}, nullptr, particleEvaluations}, D);
    }
    Mat<D> stress(const Mat<D>& F) const
    {
        Mat<D> P;
        double psi;
        material->evaluate(&F, &P, &psi, 1, HistoryOf::particles(0));
        return P;
    }
    double energy(const Mat<D>& F) const
    {
        Mat<D> P;
        double psi;
        material->evaluate(&F, &P, &psi, 1, HistoryOf::particles(0));
        return psi;
    }
    // τ = P Fᵀ (in-plane)
    Mat<D> kirchhoff(const Mat<D>& F) const { return stress(F) * F.transpose(); }
    double commit(const Mat<D>& F)
    {
        const double V0 = 1.0;
        return material->commit(&F, &V0, 0, 1);
    }
    double scalar(const std::string& name) const
    {
        double value;
        fields.find(name)->array->get(0, &value);
        return value;
    }
    double alpha() const { return scalar("equivalentPlasticStrain"); }
    // The committed Cp⁻¹ as a 3×3 (2D: the zz component from its own field).
    Eigen::Matrix3d inversePlastic() const
    {
        double values[D * D];
        fields.find("inversePlasticCauchyGreen")->array->get(0, values);
        Eigen::Matrix3d C = Eigen::Matrix3d::Identity();
        for (int i = 0; i < D; ++i)
        {
            for (int j = 0; j < D; ++j)
            {
                C(i, j) = values[i * D + j];
            }
        }
        if (D == 2)
        {
            C(2, 2) = scalar("inversePlasticCauchyGreenZZ");
        }
        return C;
    }
};

} // namespace sph::test
