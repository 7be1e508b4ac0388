// Every registered scheme, in total- and updated-Lagrangian form (the latter with a deformed
// reference configuration and non-zero K), in 1D/2D/3D (design §6, issue 4):
//   - internal force = -∂Π/∂x by central differences on a random non-trivial state;
//     hourglass control (not an energy gradient) against a direct pairwise loop instead;
//   - linear and angular momentum of the internal forces zero to round-off;
//   - zero force under rigid translation and rotation of a stress-free body.
#include "numerics/NumericsSupport.hpp"
#include "stabilisation/hourglass/Hourglass.hpp"

using namespace sph;

namespace
{

const char* kMaterial = "type neoHookean; mu 1; kappa 5; rho 1;";

// Σ x × T as a vector of the rotations of the plane(s).
template <int D>
double angularMomentum(const std::vector<Vec<D>>& x, const std::vector<Vec<D>>& T)
{
    if constexpr (D == 1)
    {
        return 0.0;
    }
    else if constexpr (D == 2)
    {
        double L = 0.0;
        for (std::size_t a = 0; a < x.size(); ++a)
        {
            L += x[a][0] * T[a][1] - x[a][1] * T[a][0];
        }
        return std::abs(L);
    }
    else
    {
        Eigen::Vector3d L = Eigen::Vector3d::Zero();
        for (std::size_t a = 0; a < x.size(); ++a)
        {
            L += Eigen::Vector3d(x[a]).cross(Eigen::Vector3d(T[a]));
        }
        return L.cwiseAbs().maxCoeff();
    }
}

template <int D>
void checkForces(const std::string& name, bool updated)
{
    INFO(name << (updated ? " UL" : " TL") << " " << D << "D");
    test::SchemeFixture<D> fixture(test::schemeCloud<D>(), test::schemeText<D>(name), kMaterial, updated,
                                   test::schemeHOverDx<D>());
    const auto x = test::deformCurrent<D>(fixture.ref.x, 17);
    ForceStatus status;
    const auto T = fixture.forces(x, &status);
    REQUIRE(status.ok());
    double maxForce = 0.0;
    double sumForce = 0.0;
    double sumMoment = 0.0;
    for (std::size_t a = 0; a < x.size(); ++a)
    {
        maxForce = std::max(maxForce, T[a].cwiseAbs().maxCoeff());
        sumForce += T[a].norm();
        sumMoment += x[a].norm() * T[a].norm();
    }
    REQUIRE(maxForce > 1e-3); // a non-trivial state

    if (name == "hourglass")
    {
        // Against a direct loop over unordered pairs, each pair once, f_b = -f_a (spec §12).
        test::SchemeFixture<D> plain(test::schemeCloud<D>(), "type none;", kMaterial, updated, test::schemeHOverDx<D>());
        const auto T0 = plain.forces(x);
        std::vector<Mat<D>> f(x.size());
        for (std::size_t a = 0; a < x.size(); ++a)
        {
            Mat<D> sum = Mat<D>::Zero();
            for (std::size_t k = fixture.ref.neighbours.begin(a) + 1; k < fixture.ref.neighbours.end(a); ++k)
            {
                const std::size_t b = fixture.ref.neighbours.indices[k];
                sum += fixture.ref.V[b] * (x[b] - x[a]) * fixture.ref.gradW(a, k).transpose();
            }
            f[a] = sum * fixture.ref.gradient.L[a].transpose();
        }
        std::vector<Vec<D>> pairForce(x.size(), Vec<D>::Zero());
        const double alphaE = 20.0 * fixture.material->youngsModulus();
        for (std::size_t a = 0; a < x.size(); ++a)
        {
            for (std::size_t k = fixture.ref.neighbours.begin(a) + 1; k < fixture.ref.neighbours.end(a); ++k)
            {
                const std::size_t b = fixture.ref.neighbours.indices[k];
                if (b < a)
                {
                    continue;
                }
                const Vec<D> xr = fixture.ref.x[b] - fixture.ref.x[a];
                const Vec<D> xc = x[b] - x[a];
                const Vec<D> unit = xc.normalized();
                const Vec<D> gamma = 0.5 * (f[a] + f[b]) * xr - xc;
                const double delta = 0.5 * gamma.dot(unit);
                const Vec<D> fa = -alphaE * fixture.V0[a] * fixture.V0[b] * fixture.ref.W[k] *
                                  delta / xr.squaredNorm() * unit;
                pairForce[a] += fa;
                pairForce[b] -= fa;
            }
        }
        double error = 0.0;
        for (std::size_t a = 0; a < x.size(); ++a)
        {
            error = std::max(error, (T[a] - T0[a] - pairForce[a]).cwiseAbs().maxCoeff());
        }
        CHECK(error < 1e-12 * maxForce);
    }
    else
    {
        const double error = test::largestForceError(fixture, x, T);
        CHECK(error / maxForce < 1e-6);
        // The energy returned with the forces is the same Π.
        std::vector<Vec<D>> T2;
        std::vector<Mat<D>> F2;
        std::vector<Mat<D>> P2;
        ForceOutput<D> out{T2, F2, P2};
        const ForceStatus withEnergy = fixture.scheme->computeForces(fixture.input(x), out, true);
        CHECK(withEnergy.strainEnergy == Approx(fixture.energy(x)).epsilon(1e-12));
    }
    Vec<D> total = Vec<D>::Zero();
    for (const auto& t : T)
    {
        total += t;
    }
    CHECK(total.cwiseAbs().maxCoeff() < 1e-13 * sumForce);
    CHECK(angularMomentum<D>(x, T) < 1e-12 * sumMoment);
}

template <int D>
Mat<D> rotation(double angle)
{
    if constexpr (D == 1)
    {
        return Mat<D>::Identity();
    }
    else if constexpr (D == 2)
    {
        Mat<D> Q;
        Q << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
        return Q;
    }
    else
    {
        return Eigen::AngleAxisd(angle, Eigen::Vector3d(0.2, 0.9, -0.4).normalized()).toRotationMatrix();
    }
}

template <int D>
void checkRigidMotion(const std::string& name, bool updated)
{
    INFO(name << (updated ? " UL" : " TL") << " " << D << "D, rigid motion");
    test::SchemeFixture<D> fixture(test::schemeCloud<D>(), test::schemeText<D>(name), kMaterial, false, test::schemeHOverDx<D>());
    if (updated)
    {
        // A stress-free reference configuration that is itself rotated: x^r = Q0 X + c0,
        // F^r = Q0, K = 0.
        const Mat<D> Q0 = rotation<D>(0.4);
        for (std::size_t a = 0; a < fixture.X.size(); ++a)
        {
            fixture.ref.x[a] = Q0 * fixture.X[a] + Vec<D>::Constant(0.3);
            fixture.ref.F[a] = Q0;
        }
        if (fixture.scheme->referenceNeeds(*fixture.kernel).gradientOfF)
        {
            fixture.ref.K.assign(fixture.X.size(), Tensor3<D>::zero());
        }
        REQUIRE(fixture.ref.rebuild(*fixture.kernel, fixture.body,
                                    fixture.scheme->referenceNeeds(*fixture.kernel).searchRadius) < 0);
        REQUIRE(fixture.scheme->prepare(fixture.ref).ok());
    }
    const Mat<D> Q = rotation<D>(1.1);
    for (int motion = 0; motion < 2; ++motion)
    {
        std::vector<Vec<D>> x(fixture.X.size());
        for (std::size_t a = 0; a < x.size(); ++a)
        {
            x[a] = (motion == 0 ? Mat<D>::Identity() : Q) * fixture.ref.x[a] + Vec<D>::Constant(2.5);
        }
        const auto T = fixture.forces(x);
        double largest = 0.0;
        for (const auto& t : T)
        {
            largest = std::max(largest, t.cwiseAbs().maxCoeff());
        }
        // Forces scale with the stiffness (mu = 1, kappa = 5) times volume: O(1).
        CHECK(largest < 1e-11);
    }
}

// The per-particle F (what contact uses for the volumes at x^{n+1}) is the force evaluation's
// F at the same positions (the same sums; the compiler may fuse them differently, so to
// round-off).
template <int D>
void checkParticleDeformationGradient(const std::string& name, bool updated)
{
    INFO(name << (updated ? " UL" : " TL") << " " << D << "D, per-particle F");
    test::SchemeFixture<D> fixture(test::schemeCloud<D>(), test::schemeText<D>(name), kMaterial, updated, test::schemeHOverDx<D>());
    const auto x = test::deformCurrent<D>(fixture.ref.x, 7);
    std::vector<Vec<D>> T;
    std::vector<Mat<D>> F;
    std::vector<Mat<D>> P;
    ForceOutput<D> out{T, F, P};
    REQUIRE(fixture.scheme->computeForces(fixture.input(x), out, false).ok());
    for (std::size_t a = 0; a < x.size(); ++a)
    {
        const Mat<D> single = fixture.scheme->deformationGradient(a, x, fixture.ref);
        CHECK((single - F[a]).norm() <= 1e-14 * F[a].norm());
    }
}

// A move of the reference configuration updates F^r and K in place (formulations/
// ReferenceManager.hpp): the new F_a and K_a read only particle a's own, so the result is the
// one computed into separate arrays, bit for bit.
template <int D>
void checkInPlaceMove(const std::string& name, bool updated)
{
    INFO(name << (updated ? " UL" : " TL") << " " << D << "D, reference moved in place");
    test::SchemeFixture<D> fixture(test::schemeCloud<D>(), test::schemeText<D>(name), kMaterial, updated, test::schemeHOverDx<D>());
    const auto x = test::deformCurrent<D>(fixture.ref.x, 5);
    const bool carriesK = !fixture.ref.K.empty();
    std::vector<Mat<D>> F;
    std::vector<Tensor3<D>> K;
    REQUIRE(fixture.scheme->referenceUpdate(x, fixture.ref, F, carriesK ? &K : nullptr).ok());
    REQUIRE(fixture.scheme->referenceUpdate(x, fixture.ref, fixture.ref.F,
                                            carriesK ? &fixture.ref.K : nullptr).ok());
    CHECK(fixture.ref.F == F);
    for (std::size_t a = 0; a < K.size(); ++a)
    {
        for (int k = 0; k < D; ++k)
        {
            REQUIRE(fixture.ref.K[a].slice[static_cast<std::size_t>(k)] ==
                    K[a].slice[static_cast<std::size_t>(k)]);
        }
    }
    if (updated)
    {
        CHECK(F != std::vector<Mat<D>>(F.size(), F.front())); // F^r varied: a real test
    }
}

// Kernel values recomputed where they are used (formulation key kernelValues recomputed): no
// W or W'/r stored, and the forces, F, P, the energy and a move of the reference are the
// stored values' bit for bit.
template <int D>
void checkRecomputedKernelValues(const std::string& name, bool updated)
{
    INFO(name << (updated ? " UL" : " TL") << " " << D << "D, kernel values recomputed");
    test::SchemeFixture<D> fixture(test::schemeCloud<D>(), test::schemeText<D>(name), kMaterial, updated, test::schemeHOverDx<D>());
    const auto x = test::deformCurrent<D>(fixture.ref.x, 3);
    const auto evaluate = [&](std::vector<Vec<D>>& T, std::vector<Mat<D>>& F, std::vector<Mat<D>>& P,
                              std::vector<Mat<D>>& Fr) {
        ForceOutput<D> out{T, F, P};
        REQUIRE(fixture.scheme->computeForces(fixture.input(x), out, false).ok());
        std::vector<Tensor3<D>> K;
        REQUIRE(fixture.scheme->referenceUpdate(x, fixture.ref, Fr, fixture.ref.K.empty() ? nullptr : &K).ok());
        return fixture.scheme->energy(fixture.input(x));
    };
    std::vector<Vec<D>> T1, T2;
    std::vector<Mat<D>> F1, F2, P1, P2, Fr1, Fr2;
    const double energy = evaluate(T1, F1, P1, Fr1);
    const bool storedW = !fixture.ref.W.empty();
    fixture.ref.recomputeKernelValues = true;
    REQUIRE(fixture.ref.rebuild(*fixture.kernel, fixture.body,
                                fixture.scheme->referenceNeeds(*fixture.kernel).searchRadius, false,
                                storedW) < 0);
    REQUIRE(fixture.scheme->prepare(fixture.ref).ok());
    CHECK(fixture.ref.W.empty());
    CHECK(fixture.ref.dWdrOverR.empty());
    CHECK(evaluate(T2, F2, P2, Fr2) == energy);
    CHECK(T2 == T1);
    CHECK(F2 == F1);
    CHECK(P2 == P1);
    CHECK(Fr2 == Fr1);
}

// A distributed run's ghosts (ForceInput::owned = 0) count in neither the strain energy nor the
// failure checks: the energies of complementary masks add up to the whole, and a particle with
// det F <= 0 is reported only while it is owned.
template <int D>
void checkOwnedParticles(const std::string& name, bool updated)
{
    INFO(name << (updated ? " UL" : " TL") << " " << D << "D, owned particles only");
    test::SchemeFixture<D> fixture(test::schemeCloud<D>(), test::schemeText<D>(name), kMaterial, updated, test::schemeHOverDx<D>());
    const std::size_t n = fixture.X.size();
    const auto energyOf = [&](const std::vector<Vec<D>>& x, const std::vector<std::uint8_t>* owned) {
        std::vector<Vec<D>> T;
        std::vector<Mat<D>> F;
        std::vector<Mat<D>> P;
        ForceOutput<D> out{T, F, P};
        ForceInput<D> in = fixture.input(x);
        in.owned = owned;
        return fixture.scheme->computeForces(in, out, true);
    };
    const auto x = test::deformCurrent<D>(fixture.ref.x, 7);
    std::vector<std::uint8_t> firstHalf(n, 0), secondHalf(n, 1);
    for (std::size_t a = 0; a < n / 2; ++a)
    {
        firstHalf[a] = 1;
        secondHalf[a] = 0;
    }
    const ForceStatus all = energyOf(x, nullptr);
    const ForceStatus first = energyOf(x, &firstHalf);
    const ForceStatus second = energyOf(x, &secondHalf);
    REQUIRE(all.ok());
    CHECK(first.strainEnergy != 0.0);
    CHECK(second.strainEnergy != 0.0);
    CHECK(std::abs(first.strainEnergy + second.strainEnergy - all.strainEnergy) <=
          1e-12 * std::abs(all.strainEnergy));

    // Mirrored, every particle has det F < 0: the first owned one is reported, and none when
    // every particle is a ghost.
    auto mirrored = x;
    for (auto& p : mirrored)
    {
        p[0] = -p[0];
    }
    CHECK(energyOf(mirrored, nullptr).badParticle == 0);
    std::vector<std::uint8_t> one(n, 0);
    one[n / 3] = 1;
    const ForceStatus onlyOne = energyOf(mirrored, &one);
    CHECK(onlyOne.failure == FailureKind::nonPositiveJacobian);
    CHECK(onlyOne.badParticle == static_cast<long>(n / 3));
    const std::vector<std::uint8_t> none(n, 0);
    CHECK(energyOf(mirrored, &none).ok());

    // The same for a move of the reference configuration to the mirrored positions.
    const auto moveReference = [&](const std::vector<std::uint8_t>* owned) {
        std::vector<Mat<D>> Fr;
        std::vector<Tensor3<D>> K;
        fixture.ref.owned = owned;
        const ForceStatus status = fixture.scheme->referenceUpdate(
            mirrored, fixture.ref, Fr, fixture.ref.K.empty() ? nullptr : &K);
        fixture.ref.owned = nullptr;
        return status;
    };
    CHECK(moveReference(nullptr).badParticle == 0);
    CHECK(moveReference(&one).badParticle == static_cast<long>(n / 3));
    CHECK(moveReference(&none).ok());
}

template <int D>
void checkAllSchemes()
{
    test::loadModelLibraries();
    auto names = Registry<Stabilisation<D>>::names();
    REQUIRE(names.size() >= 4);
    names.push_back("gradF fit joint"); // a variant with its own kinematics (§G17)
    for (const std::string& name : names)
    {
        for (const bool updated : {false, true})
        {
            checkForces<D>(name, updated);
            checkRigidMotion<D>(name, updated);
            checkParticleDeformationGradient<D>(name, updated);
            checkOwnedParticles<D>(name, updated);
            checkInPlaceMove<D>(name, updated);
            checkRecomputedKernelValues<D>(name, updated);
        }
    }
}

} // namespace

TEST_CASE("every scheme's force is -dPi/dx and conserves momentum (1D)", "[scheme]")
{
    checkAllSchemes<1>();
}

TEST_CASE("every scheme's force is -dPi/dx and conserves momentum (2D)", "[scheme]")
{
    checkAllSchemes<2>();
}

TEST_CASE("every scheme's force is -dPi/dx and conserves momentum (3D)", "[scheme]")
{
    checkAllSchemes<3>();
}

TEST_CASE("vidal with beta = 0 reproduces none exactly", "[scheme][vidal]")
{
    const auto points = test::schemeCloud<2>();
    for (const bool updated : {false, true})
    {
        test::SchemeFixture<2> none(points, "type none;", kMaterial, updated);
        test::SchemeFixture<2> vidal(points, "type vidal; beta (0 0);", kMaterial, updated);
        const auto x = test::deformCurrent<2>(none.ref.x, 3);
        const auto Tn = none.forces(x);
        const auto Tv = vidal.forces(x);
        for (std::size_t a = 0; a < x.size(); ++a)
        {
            CHECK(Tn[a] == Tv[a]);
        }
        CHECK(none.energy(x) == vidal.energy(x));
    }
}

TEST_CASE("vidal with beta != 0 differs from none but keeps linear completeness", "[scheme][vidal]")
{
    const auto points = test::schemeCloud<2>();
    test::SchemeFixture<2> none(points, "type none;", kMaterial, false);
    test::SchemeFixture<2> vidal(points, "type vidal; beta (0.3 0);", kMaterial, false);
    // An affine deformation gives the same F (exact gradient) hence the same energy.
    Mat<2> A;
    A << 1.05, 0.02, -0.03, 0.97;
    std::vector<Vec<2>> x(points.size());
    for (std::size_t a = 0; a < x.size(); ++a)
    {
        x[a] = A * points[a];
    }
    CHECK(vidal.energy(x) == Approx(none.energy(x)).epsilon(1e-12));
    const auto y = test::deformCurrent<2>(points, 9);
    CHECK(std::abs(vidal.energy(y) - none.energy(y)) > 1e-6 * none.energy(y));
}
