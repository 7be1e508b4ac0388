// Monaghan's artificial viscosity (artificialViscosity/monaghan/Monaghan.cpp) on random clouds
// in 2D and 3D: the pair forces conserve linear (and angular) momentum to round-off, vanish for
// rigid translation, rigid rotation and separating particles, only take kinetic energy, spare
// fixed particles, raise the speed that bounds the time step and do not depend on the number
// of threads; `none` never acts.
#include "artificialViscosity/ArtificialViscosity.hpp"
#include "numerics/NumericsSupport.hpp"

#include <Eigen/Geometry>
#include <omp.h>

using namespace sph;

namespace
{

// A perturbed lattice (spacing 1, h = 1.5) of one body of stiff elastic material
// (c0 = 116 m/s in 2D), with masses and det F varying from particle to particle.
template <int D>
struct Cloud
{
    ParticleSet<D> p;
    std::unique_ptr<Kernel> kernel = test::makeKernel("cubicSpline", D, 1.0, 1.5);
    std::unique_ptr<Material<D>> material =
        test::build<Material<D>>("type linearElastic; E 1e7; nu 0.3; rho 1000;", {}, D);

    explicit Cloud(unsigned seed, int perSide = D == 2 ? 7 : 4)
    {
        const auto points = test::lattice<D>(perSide, 0.2, seed);
        p.resize(points.size());
        std::mt19937 random(seed + 1);
        std::uniform_real_distribution<double> uniform(-1.0, 1.0);
        for (std::size_t a = 0; a < p.size(); ++a)
        {
            p.X[a] = points[a];
            p.x[a] = points[a];
            p.V0[a] = 1.0 + 0.2 * uniform(random);
            p.m[a] = 1000.0 * p.V0[a];
            p.F[a] = Mat<D>::Identity() * (1.0 + 0.05 * uniform(random));
        }
        p.bodies = {BodyRange{"block", 0, p.size()}};
    }

    std::unique_ptr<ArtificialViscosity<D>> viscosity(const std::string& text) const
    {
        return test::build<ArtificialViscosity<D>>(text, {kernel.get(), {material.get()}}, D);
    }

    // The viscous accelerations for velocities v.
    std::vector<Vec<D>> accelerations(ArtificialViscosity<D>& model,
                                      const std::vector<Vec<D>>& v) const
    {
        std::vector<Vec<D>> a;
        model.compute({p.x, v, p}, a);
        return a;
    }

    std::vector<Vec<D>> randomVelocities(unsigned seed, double compression = 0.0) const
    {
        std::mt19937 random(seed);
        std::uniform_real_distribution<double> uniform(-1.0, 1.0);
        std::vector<Vec<D>> v(p.size());
        for (std::size_t a = 0; a < p.size(); ++a)
        {
            for (int d = 0; d < D; ++d)
            {
                v[a][d] = uniform(random);
            }
            v[a] -= compression * p.x[a];
        }
        return v;
    }
};

template <int D>
double largest(const std::vector<Vec<D>>& a)
{
    double m = 0.0;
    for (const auto& x : a)
    {
        m = std::max(m, x.norm());
    }
    return m;
}

template <int D>
void checkMomentum(unsigned seed)
{
    const Cloud<D> cloud(seed);
    auto model = cloud.viscosity("type monaghan; alpha 1; beta 2;");
    const auto a = cloud.accelerations(*model, cloud.randomVelocities(seed + 7));
    Vec<D> momentum = Vec<D>::Zero();
    Eigen::Vector3d angular = Eigen::Vector3d::Zero();
    double scale = 0.0;
    double angularScale = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        const Vec<D> force = cloud.p.m[i] * a[i];
        momentum += force;
        scale += force.norm();
        angular += embed<D>(cloud.p.x[i]).cross(embed<D>(force));
        angularScale += cloud.p.x[i].norm() * force.norm();
    }
    INFO(D << "D, seed " << seed << ": |sum m a| " << momentum.norm() << " of " << scale);
    REQUIRE(scale > 0.0);
    CHECK(momentum.norm() < 1e-14 * scale);
    CHECK(angular.norm() < 1e-14 * angularScale);
}

template <int D>
void checkRigidAndSeparating()
{
    const Cloud<D> cloud(11);
    auto model = cloud.viscosity("type monaghan; alpha 1; beta 2;");
    const double reference = largest<D>(cloud.accelerations(*model, cloud.randomVelocities(3)));
    REQUIRE(reference > 0.0);
    std::vector<Vec<D>> translation(cloud.p.size(), Vec<D>::Constant(0.8));
    std::vector<Vec<D>> rotation(cloud.p.size());
    std::vector<Vec<D>> expansion(cloud.p.size());
    for (std::size_t a = 0; a < cloud.p.size(); ++a)
    {
        const Vec<D>& x = cloud.p.x[a];
        if constexpr (D == 2)
        {
            rotation[a] = Vec<D>(-0.7 * x[1], 0.7 * x[0]) + translation[a];
        }
        else
        {
            rotation[a] = Vec<D>(0.3, -0.5, 0.7).cross(x) + translation[a];
        }
        expansion[a] = 0.4 * x + translation[a];
    }
    CHECK(largest<D>(cloud.accelerations(*model, translation)) == 0.0);
    CHECK(largest<D>(cloud.accelerations(*model, expansion)) == 0.0);
    // v_ab·x_ab = (ω × x_ab)·x_ab = 0 up to the rounding of v_ab.
    const double rotating = largest<D>(cloud.accelerations(*model, rotation));
    INFO(D << "D: rotation " << rotating << " against " << reference);
    CHECK(rotating < 1e-12 * reference);
}

// d(kinetic)/dt of the viscous forces alone, Σ m v·a.
template <int D>
double power(const Cloud<D>& cloud, const std::vector<Vec<D>>& v, const std::vector<Vec<D>>& a)
{
    double p = 0.0;
    for (std::size_t i = 0; i < v.size(); ++i)
    {
        p += cloud.p.m[i] * v[i].dot(a[i]);
    }
    return p;
}

} // namespace

TEST_CASE("monaghan viscosity conserves momentum on random clouds (2D, 3D)", "[viscosity]")
{
    for (const unsigned seed : {1u, 2u, 3u})
    {
        checkMomentum<2>(seed);
        checkMomentum<3>(seed);
    }
}

TEST_CASE("monaghan viscosity vanishes for rigid motion and separating particles",
          "[viscosity]")
{
    checkRigidAndSeparating<2>();
    checkRigidAndSeparating<3>();
}

TEST_CASE("monaghan viscosity only takes kinetic energy", "[viscosity]")
{
    const Cloud<2> cloud2(5);
    const Cloud<3> cloud3(5);
    for (const std::string text : {"type monaghan;", "type monaghan; alpha 1; beta 0;",
                                   "type monaghan; alpha 0; beta 2;"})
    {
        INFO(text);
        for (const unsigned seed : {1u, 2u, 3u})
        {
            // A compressive field (v = -0.5 x + noise) and a purely random one.
            for (const double compression : {0.5, 0.0})
            {
                auto model2 = cloud2.viscosity(text);
                const auto v2 = cloud2.randomVelocities(seed, compression);
                const double p2 = power(cloud2, v2, cloud2.accelerations(*model2, v2));
                auto model3 = cloud3.viscosity(text);
                const auto v3 = cloud3.randomVelocities(seed, compression);
                const double p3 = power(cloud3, v3, cloud3.accelerations(*model3, v3));
                INFO("seed " << seed << ", compression " << compression << ": dK/dt " << p2
                             << " (2D), " << p3 << " (3D)");
                CHECK(p2 < 0.0);
                CHECK(p3 < 0.0);
            }
        }
    }
}

TEST_CASE("monaghan viscosity spares fixed particles and bounds the time step", "[viscosity]")
{
    Cloud<2> cloud(7);
    cloud.p.fixed[3] = 1;
    auto model = cloud.viscosity("type monaghan; alpha 0.5; beta 1;");
    const double c = 150.0;
    CHECK(model->signalSpeed(c) == Approx(c * (1.0 + 1.2 * 0.5))); // no pair compressed yet
    const auto a = cloud.accelerations(*model, cloud.randomVelocities(4, 0.5));
    CHECK(a[3].norm() == 0.0);
    // c + 1.2 (alpha c + beta mu_max), mu_max > 0 for a compressive field.
    CHECK(model->signalSpeed(c) > c * (1.0 + 1.2 * 0.5));
    auto none = cloud.viscosity("type none;");
    CHECK(!none->active());
    CHECK(none->signalSpeed(c) == c);
}

TEST_CASE("monaghan viscosity: negative coefficients and unknown keys are input errors",
          "[viscosity][errors]")
{
    const Cloud<2> cloud(1);
    CHECK_THROWS_WITH(cloud.viscosity("type monaghan; alpha -1;"),
                      Catch::Contains("alpha = -1 must lie in [0, inf)"));
    CHECK_THROWS_WITH(cloud.viscosity("type monaghan; beta -2;"),
                      Catch::Contains("beta = -2 must lie in [0, inf)"));
    CHECK_THROWS_WITH(cloud.viscosity("type monaghan; alhpa 1;"), Catch::Contains("alhpa"));
    CHECK_THROWS_WITH(cloud.viscosity("type monagan;"), Catch::Contains("monaghan"));
}

TEST_CASE("monaghan viscosity: one and two threads give the same bits", "[viscosity][threads]")
{
    // 1296 particles in 2D, 1331 in 3D: above the size at which the loops use threads.
    const auto check = [](const auto& cloud) {
        auto model = cloud.viscosity("type monaghan; alpha 1; beta 2;");
        const auto v = cloud.randomVelocities(9, 0.3);
        const int threads = omp_get_max_threads();
        omp_set_num_threads(1);
        const auto one = cloud.accelerations(*model, v);
        const double speedOne = model->signalSpeed(100.0);
        omp_set_num_threads(2);
        const auto two = cloud.accelerations(*model, v);
        omp_set_num_threads(threads);
        CHECK(one == two);
        CHECK(speedOne == model->signalSpeed(100.0));
    };
    check(Cloud<2>(4, 36));
    check(Cloud<3>(4, 11));
}
