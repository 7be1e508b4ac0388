// gradF with `fit joint` (docs/theory/gradF-plastic.md §G17): f_a and H_a from one least-squares
// fit of the second-order Taylor expansion.
//   - a quadratic motion on a perturbed cloud: every sample F_b(a) is the motion's F at b, at
//     every particle, the free surface included (where the paper's sequential fit is not exact:
//     checked, so that the test can tell the two apart);
//   - an affine motion: G = 0 and the energy of `none`, as the sequential fit.
// The force (−∂Π/∂x by finite differences, momentum, rigid motions, ghosts, moves) is checked
// with every scheme in SchemeForceTest.cpp ("gradF fit joint").
#include "numerics/NumericsSupport.hpp"
#include "stabilisation/gradF/GradF.hpp"

using namespace sph;

namespace
{

const char* kMaterial = "type neoHookean; mu 1; kappa 5; rho 1;";

template <int D>
struct QuadraticMotion
{
    Mat<D> A = Mat<D>::Identity();
    Tensor3<D> H0 = Tensor3<D>::zero();
    QuadraticMotion()
    {
        for (int i = 0; i < D; ++i)
        {
            for (int j = 0; j < D; ++j)
            {
                A(i, j) += 0.1 * std::cos(2.0 + 5 * i + 3 * j);
                for (int k = j; k < D; ++k)
                {
                    const double value = 0.05 * std::sin(1.0 + i + 2 * j + 4 * k);
                    H0(i, j, k) = value;
                    H0(i, k, j) = value;
                }
            }
        }
    }
    Vec<D> at(const Vec<D>& X) const { return A * X + 0.5 * H0.contract(X) * X; }
    Mat<D> gradient(const Vec<D>& X) const { return A + H0.contract(X); }
};

// The largest |F_b(a) − F(X_b)| over all samples of all particles.
template <int D>
double largestSampleError(const std::string& scheme, const std::vector<Vec<D>>& points)
{
    test::SchemeFixture<D> fixture(points, scheme, kMaterial, false, D == 3 ? 1.6 : 1.4);
    const QuadraticMotion<D> motion;
    std::vector<Vec<D>> x(points.size());
    for (std::size_t a = 0; a < x.size(); ++a)
    {
        x[a] = motion.at(points[a]);
    }
    const auto& gradF = dynamic_cast<const GradF<D>&>(*fixture.scheme);
    const NeighbourList& list = fixture.ref.neighbours;
    double error = 0.0;
    for (std::size_t a = 0; a < x.size(); ++a)
    {
        const auto kin = gradF.kinematics(a, x, fixture.ref);
        for (std::size_t k = list.begin(a); k < list.end(a); ++k)
        {
            const std::size_t b = list.indices[k];
            const Mat<D> sample = kin.F + kin.G.contract(Vec<D>(points[b] - points[a]));
            error = std::max(error, (sample - motion.gradient(points[b])).cwiseAbs().maxCoeff());
        }
    }
    return error;
}

template <int D>
void checkQuadraticEverywhere(int n)
{
    INFO(D << "D perturbed cloud, quadratic motion");
    const auto points = test::lattice<D>(n, 0.2, 3);
    CHECK(largestSampleError<D>("type gradF; fit joint;", points) < 1e-11);
    CHECK(largestSampleError<D>("type gradF;", points) > 1e-4); // the sequential fit is not
}

template <int D>
void checkAffine(int n)
{
    INFO(D << "D perturbed cloud, affine motion");
    const auto points = test::lattice<D>(n, 0.2, 4);
    test::SchemeFixture<D> joint(points, "type gradF; fit joint;", kMaterial, false,
                                 D == 3 ? 1.6 : 1.4);
    test::SchemeFixture<D> none(points, "type none;", kMaterial, false, D == 3 ? 1.6 : 1.4);
    const QuadraticMotion<D> motion;
    std::vector<Vec<D>> x(points.size());
    for (std::size_t a = 0; a < x.size(); ++a)
    {
        x[a] = motion.A * points[a] + Vec<D>::Constant(0.5);
    }
    const auto& gradF = dynamic_cast<const GradF<D>&>(*joint.scheme);
    double worstG = 0.0;
    for (std::size_t a = 0; a < x.size(); ++a)
    {
        for (const auto& slice : gradF.kinematics(a, x, joint.ref).G.slice)
        {
            worstG = std::max(worstG, slice.cwiseAbs().maxCoeff());
        }
    }
    CHECK(worstG < 1e-12);
    CHECK(joint.energy(x) == Approx(none.energy(x)).epsilon(1e-13));
}

} // namespace

TEST_CASE("gradF fit joint: every sample exact for a quadratic motion, free surface included",
          "[gradF][joint]")
{
    checkQuadraticEverywhere<1>(12);
    checkQuadraticEverywhere<2>(8);
    checkQuadraticEverywhere<3>(5);
}

TEST_CASE("gradF fit joint: G = 0 and the energy of none for affine motions", "[gradF][joint]")
{
    checkAffine<1>(15);
    checkAffine<2>(8);
    checkAffine<3>(5);
}
