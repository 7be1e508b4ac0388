// Family contract, run on every registered kernel in 1D, 2D and 3D (design §6):
// unit integral by quadrature, compact support, dW/dr consistent with W, W >= 0.
#include "numerics/NumericsSupport.hpp"

#include <numbers>

using namespace sph;

namespace
{

// ∫ W over R^d for a radial W, by composite Simpson in r (the measure r^{d-1} is smooth).
double integral(const Kernel& kernel, int dim)
{
    const double R = kernel.supportRadius();
    const int n = 200000;
    const double dr = R / n;
    double sum = 0.0;
    for (int i = 0; i <= n; ++i)
    {
        const double r = i * dr;
        const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        const double measure = dim == 1 ? 2.0 : dim == 2 ? 2.0 * std::numbers::pi * r
                                                        : 4.0 * std::numbers::pi * r * r;
        sum += weight * kernel.W(r) * measure;
    }
    return sum * dr / 3.0;
}

} // namespace

TEST_CASE("kernel contract holds for every registered kernel", "[kernel]")
{
    test::loadModelLibraries();
    const auto names = Registry<Kernel>::names();
    REQUIRE(names.size() >= 3);
    for (const std::string& name : names)
    {
        for (int dim = 1; dim <= 3; ++dim)
        {
            for (double spacing : {1.0, 2.5e-3})
            {
                const auto kernel = test::makeKernel(name, dim, spacing, 1.3);
                INFO(name << " in " << dim << "D, spacing " << spacing);
                CHECK(kernel->h() == Approx(1.3 * spacing));
                CHECK(integral(*kernel, dim) == Approx(1.0).margin(1e-6));
                const double R = kernel->supportRadius();
                // Compact support.
                CHECK(kernel->W(R) == 0.0);
                CHECK(kernel->W(1.5 * R) == 0.0);
                CHECK(kernel->dWdr(R * 1.0001) == 0.0);
                // dW/dr is the derivative of W (so ∇W = W'(r) r̂ is odd and consistent).
                for (double q : {0.05, 0.3, 0.7, 0.99, 1.01, 1.4, 1.9, 2.3, 2.9})
                {
                    const double r = q * kernel->h();
                    if (r >= R)
                    {
                        continue;
                    }
                    const double step = 1e-6 * kernel->h();
                    const double numeric = (kernel->W(r + step) - kernel->W(r - step)) / (2 * step);
                    CHECK(kernel->dWdr(r) == Approx(numeric).epsilon(1e-6).margin(1e-9 * kernel->W(0) / kernel->h()));
                    CHECK(kernel->W(r) >= 0.0);
                    CHECK(kernel->dWdr(r) <= 0.0); // monotone decreasing
                }
                CHECK(kernel->dWdr(0.0) == 0.0); // smooth peak: ∇W continuous and odd
                // The batch call agrees with the scalar one.
                const double r[3] = {0.1 * kernel->h(), 0.9 * kernel->h(), 1.7 * kernel->h()};
                double w[3];
                double dw[3];
                kernel->evaluate(r, 3, w, dw);
                for (int i = 0; i < 3; ++i)
                {
                    CHECK(w[i] == kernel->W(r[i]));
                    CHECK(dw[i] == kernel->dWdr(r[i]));
                }
            }
        }
    }
}

TEST_CASE("the cubic spline matches spec §1 values", "[kernel]")
{
    const auto kernel = test::makeKernel("cubicSpline", 2, 1.0, 1.0);
    const double sigma = 10.0 / (7.0 * std::numbers::pi);
    CHECK(kernel->W(0.0) == Approx(sigma));
    CHECK(kernel->W(1.0) == Approx(sigma * 0.25));
    CHECK(kernel->W(1.5) == Approx(sigma * 0.25 * 0.125));
    CHECK(kernel->dWdr(0.5) == Approx(sigma * (-1.5 + 2.25 * 0.25)));
}
