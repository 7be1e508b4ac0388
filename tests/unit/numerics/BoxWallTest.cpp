// The `box` wall (walls/box/BoxWall.cpp): its signed distance and outward normal off a face, off
// an edge or a corner (from the edge or corner point), inside (the nearest face), at a time t
// when it moves; the normal is the gradient of the distance, so that the contact force of
// walls/WallSet.hpp is conservative round the corners; min must lie below max. Then through
// WallSet: a particle near a corner is pushed away from the corner point with k δ, the force is
// -∂Φ/∂x, friction opposes the sliding along the face of a moving box, and the loads are the
// force on the particles.
#include "materials/Material.hpp"
#include "numerics/NumericsSupport.hpp"
#include "walls/WallSet.hpp"

#include <random>

using namespace sph;

namespace
{

template <int D>
std::unique_ptr<Wall<D>> box(const std::string& keys)
{
    return test::build<Wall<D>>("type box; " + keys, {{"block"}}, D,
                                Selection::withBodies({"block"}));
}

template <int D>
void checkSide(const Wall<D>& wall, const Vec<D>& x, double t, double distance,
               const Vec<D>& normal)
{
    const auto side = wall.side(x, t);
    INFO("x = (" << x.transpose() << "), t = " << t << ": distance " << side.distance
                 << ", normal (" << side.normal.transpose() << ")");
    CHECK(side.distance == Approx(distance).margin(1e-12));
    CHECK((side.normal - normal).norm() < 1e-12);
}

// A 2D footing: [-0.05, 0.05] x [0.2, 0.3].
const std::string footing = "min (-0.05 0.2); max (0.05 0.3);";

// The normal is ∇d (central differences) at random points round and inside the box [0, 1] x
// [0, 2] (x [0, 3]), but for those near the medial axis inside, where two faces are equally
// near and d has a kink.
template <int D>
void checkNormalIsGradient(const Wall<D>& wall, const Vec<D>& upper)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(-0.5, 1.5);
    const double h = 1e-6;
    int inside = 0;
    int outside = 0;
    for (int n = 0; n < 2000; ++n)
    {
        Vec<D> x;
        for (int d = 0; d < D; ++d)
        {
            x[d] = uniform(random) * upper[d];
        }
        const Vec<D> depths[2] = {x, upper - x};
        const bool isInside = (x.array() > 0.0).all() && (x.array() < upper.array()).all();
        if (isInside)
        {
            std::vector<double> all;
            for (const Vec<D>& depth : depths)
            {
                all.insert(all.end(), depth.data(), depth.data() + D);
            }
            std::sort(all.begin(), all.end());
            if (all[1] - all[0] < 10 * h)
            {
                continue;
            }
        }
        const auto side = wall.side(x, 0.0);
        Vec<D> gradient;
        for (int d = 0; d < D; ++d)
        {
            Vec<D> step = Vec<D>::Zero();
            step[d] = h;
            gradient[d] =
                (wall.side(x + step, 0.0).distance - wall.side(x - step, 0.0).distance) / (2 * h);
        }
        INFO("x = (" << x.transpose() << "), d = " << side.distance << ", normal ("
                     << side.normal.transpose() << "), gradient (" << gradient.transpose() << ")");
        CHECK(std::abs(side.normal.norm() - 1.0) < 1e-12);
        CHECK((gradient - side.normal).norm() < 1e-6);
        (isInside ? inside : outside) += 1;
    }
    CHECK(inside > 100);
    CHECK(outside > 100);
}

} // namespace

TEST_CASE("box wall: off a face, the distance to it along its outward normal", "[walls][box]")
{
    const auto wall = box<2>(footing);
    checkSide<2>(*wall, {0.0, 0.1}, 0.0, 0.1, {0.0, -1.0});   // below the footing
    checkSide<2>(*wall, {0.02, 0.35}, 0.0, 0.05, {0.0, 1.0}); // above
    checkSide<2>(*wall, {0.08, 0.25}, 0.0, 0.03, {1.0, 0.0}); // right
    checkSide<2>(*wall, {-0.09, 0.22}, 0.0, 0.04, {-1.0, 0.0});
    checkSide<2>(*wall, {0.05, 0.2}, 0.0, 0.0, {0.0, -1.0}); // on the boundary, at the corner
    const auto cube = box<3>("min (0 0 0); max (1 2 3);");
    checkSide<3>(*cube, {0.5, 1.0, 3.25}, 0.0, 0.25, {0.0, 0.0, 1.0});
    checkSide<3>(*cube, {0.5, -0.5, 2.0}, 0.0, 0.5, {0.0, -1.0, 0.0});
}

TEST_CASE("box wall: off an edge or a corner, the distance from that point and the normal away "
          "from it",
          "[walls][box]")
{
    const auto wall = box<2>(footing);
    // 3-4-5 triangles from the corners (0.05, 0.2) and (-0.05, 0.3).
    checkSide<2>(*wall, {0.05 + 0.03, 0.2 - 0.04}, 0.0, 0.05, {0.6, -0.8});
    checkSide<2>(*wall, {-0.05 - 0.04, 0.3 + 0.03}, 0.0, 0.05, {-0.8, 0.6});
    const auto cube = box<3>("min (0 0 0); max (1 2 3);");
    checkSide<3>(*cube, {1.3, 2.4, 1.5}, 0.0, 0.5, {0.6, 0.8, 0.0});          // the edge x=1, y=2
    checkSide<3>(*cube, {-0.2, -0.3, -0.6}, 0.0, 0.7, Vec<3>(-2, -3, -6) / 7); // the corner 0
    checkSide<3>(*cube, {1.2, 2.3, 3.6}, 0.0, 0.7, Vec<3>(2, 3, 6) / 7);       // the corner max
}

TEST_CASE("box wall: inside, minus the depth below the nearest face and its normal",
          "[walls][box]")
{
    const auto wall = box<2>(footing);
    checkSide<2>(*wall, {0.0, 0.21}, 0.0, -0.01, {0.0, -1.0});
    checkSide<2>(*wall, {0.04, 0.28}, 0.0, -0.01, {1.0, 0.0});
    checkSide<2>(*wall, {-0.03, 0.27}, 0.0, -0.02, {-1.0, 0.0});
    checkSide<2>(*wall, {0.0, 0.26}, 0.0, -0.04, {0.0, 1.0});
    const auto cube = box<3>("min (0 0 0); max (1 2 3);");
    checkSide<3>(*cube, {0.5, 1.0, 2.9}, 0.0, -0.1, {0.0, 0.0, 1.0});
    checkSide<3>(*cube, {0.5, 0.2, 1.5}, 0.0, -0.2, {0.0, -1.0, 0.0});
}

TEST_CASE("box wall: moving, the box at t is the box at 0 moved by velocity t", "[walls][box]")
{
    const auto wall = box<2>(footing + " velocity (0.002 -0.001);");
    const double t = 10.0; // moved by (0.02, -0.01): [-0.03, 0.07] x [0.19, 0.29]
    checkSide<2>(*wall, {0.0, 0.1}, 0.0, 0.1, {0.0, -1.0});
    checkSide<2>(*wall, {0.0, 0.1}, t, 0.09, {0.0, -1.0});
    checkSide<2>(*wall, {0.07 + 0.03, 0.19 - 0.04}, t, 0.05, {0.6, -0.8});
    checkSide<2>(*wall, {0.06, 0.2}, t, -0.01, {0.0, -1.0});
    CHECK(wall->moves());
    CHECK(wall->velocity() == Vec<2>(0.002, -0.001));
}

TEST_CASE("box wall: the normal is the gradient of the distance (2D and 3D)", "[walls][box]")
{
    checkNormalIsGradient<2>(*box<2>("min (0 0); max (1 2);"), {1.0, 2.0});
    checkNormalIsGradient<3>(*box<3>("min (0 0 0); max (1 2 3);"), {1.0, 2.0, 3.0});
}

TEST_CASE("box wall: in 1D an interval", "[walls][box]")
{
    const auto wall = box<1>("min (0); max (1);");
    checkSide<1>(*wall, Vec<1>(-0.5), 0.0, 0.5, Vec<1>(-1.0));
    checkSide<1>(*wall, Vec<1>(1.2), 0.0, 0.2, Vec<1>(1.0));
    checkSide<1>(*wall, Vec<1>(0.3), 0.0, -0.3, Vec<1>(-1.0));
    checkSide<1>(*wall, Vec<1>(0.8), 0.0, -0.2, Vec<1>(1.0));
}

TEST_CASE("box wall: max must lie above min in every component", "[walls][box]")
{
    // "model { type box; min (-0.05 0.3); max (0.05 0.2); }": the second component of max.
    test::requireInputError([] { box<2>("min (-0.05 0.3); max (0.05 0.2);"); }, 1, 46,
                            "box: max y = 0.2 must lie in (0.3, inf), above min y = 0.3");
    test::requireInputError([] { box<2>("min (0.05 0.2); max (0.05 0.3);"); }, 1, 40,
                            "box: max x = 0.05 must lie in (0.05, inf), above min x = 0.05");
    test::requireInputError([] { box<3>("min (0 0 1); max (1 1 -1);"); }, 1, 41,
                            "box: max z = -1 must lie in (1, inf), above min z = 1");
}

TEST_CASE("box wall in a WallSet: pushed away from the corner point, conservative, with "
          "friction along a moving face",
          "[walls][box]")
{
    // One particle of a stiff block (c0 = 116 m/s) of spacing s = 1 cm: r0 = 5 mm, k = ρ c0².
    const double s = 0.01;
    const auto material =
        test::build<Material<2>>("type linearElastic; E 1e7; nu 0.3; rho 1000;", {}, 2);
    const double c0 = material->waveSpeed(Mat<2>::Identity());
    const double k = 1000.0 * c0 * c0;
    ParticleSet<2> p;
    p.resize(1);
    p.V0[0] = s * s;
    p.m[0] = 1000.0 * s * s;
    p.bodies = {BodyRange{"block", 0, 1}};
    const auto walls = test::parse("footing { type box; " + footing +
                                   " velocity (0 -0.001); friction 0.5; }");
    WallSet<2> set(walls.get(), {"block"}, {material.get()}, s);
    // Moving with the footing: nothing slides, no friction.
    const std::vector<Vec<2>> v{Vec<2>(0.0, -0.001)};
    const auto forceAt = [&](const Vec<2>& x, double t, const std::vector<Vec<2>>& velocity) {
        p.x[0] = x;
        std::vector<Vec<2>> a{Vec<2>::Zero()};
        set.applyForces(p, velocity, t, 1e-5, a);
        return Vec<2>(p.m[0] * a[0]);
    };

    // 3 mm from the corner (0.05, 0.2) along (0.6, -0.8): δ = 2 mm, pushed along (0.6, -0.8).
    const Vec<2> corner(0.05, 0.2);
    const Vec<2> away(0.6, -0.8);
    const Vec<2> x = corner + 0.003 * away;
    const Vec<2> force = forceAt(x, 0.0, v);
    CHECK((force - k * 0.002 * away).norm() < 1e-9 * k * 0.002);
    CHECK(set.potential() == Approx(0.5 * k * 0.002 * 0.002).epsilon(1e-12));
    CHECK((set.loads().force[0] - force).norm() == 0.0);
    CHECK((set.loads().normalForce[0] - force).norm() == 0.0);
    // At t = 1 s the footing has moved down by 1 mm: the particle is 2 mm from the corner.
    CHECK((forceAt(x, 1.0, v) - k * (0.005 - std::hypot(0.0018, -0.0014)) *
                                    Vec<2>(0.0018, -0.0014).normalized())
              .norm() < 1e-6);

    // F = -∂Φ/∂x round the corner, off the faces and inside (central differences of Φ).
    for (const Vec<2>& at : {x, Vec<2>(corner + Vec<2>(0.002, -0.001)),
                             Vec<2>(corner + Vec<2>(0.001, 0.002)), Vec<2>(0.0, 0.197),
                             Vec<2>(0.049, 0.2005)})
    {
        const Vec<2> f = forceAt(at, 0.0, v);
        const double h = 1e-8;
        Vec<2> gradient;
        for (int d = 0; d < 2; ++d)
        {
            Vec<2> step = Vec<2>::Zero();
            step[d] = h;
            forceAt(at + step, 0.0, v);
            const double plus = set.potential();
            forceAt(at - step, 0.0, v);
            gradient[d] = (plus - set.potential()) / (2 * h);
        }
        INFO("x = (" << at.transpose() << "): force (" << f.transpose() << "), -grad Phi ("
                     << -gradient.transpose() << ")");
        CHECK(f.norm() > 0.0);
        CHECK((f + gradient).norm() < 1e-5 * f.norm());
    }

    // Under the base, sliding at 10 m/s along it relative to the footing: the friction is
    // μ F_n against the sliding (too weak to stop it within the step).
    const Vec<2> under(0.0, 0.197);
    const double normal = k * 0.002;
    const Vec<2> sliding = forceAt(under, 0.0, {Vec<2>(10.0, -0.001)});
    CHECK(sliding[1] == Approx(-normal).epsilon(1e-12));
    CHECK(sliding[0] == Approx(-0.5 * normal).epsilon(1e-12));
    CHECK(set.loads().normalForce[0].norm() == Approx(normal).epsilon(1e-12));
}
