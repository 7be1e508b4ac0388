#include "particles/Parallel.hpp"
#include "particles/ReferenceConfiguration.hpp"

#include <cmath>

namespace sph
{

template <int D>
void ReferenceConfiguration<D>::setInitial(const ParticleSet<D>& particles, bool withGradient)
{
    x = particles.X;
    V = particles.V0;
    F.assign(particles.size(), Mat<D>::Identity());
    if (withGradient)
    {
        K.assign(particles.size(), Tensor3<D>::zero());
    }
    else
    {
        K.clear();
    }
}

template <int D>
long ReferenceConfiguration<D>::rebuild(const Kernel& kernel, const std::vector<int>& body,
                                        double radius)
{
    searchRadius = radius;
    neighbours = buildNeighbourList<D>(x, body, radius);
    const std::size_t pairs = neighbours.pairCount();
    W.resize(pairs);
    gradW.resize(pairs);
    const std::size_t n = size();
#pragma omp parallel if (useThreads(n))
    {
        std::vector<double> r;
        std::vector<double> w;
        std::vector<double> dw;
#pragma omp for schedule(static)
        for (std::size_t a = 0; a < n; ++a)
        {
            const std::size_t first = neighbours.begin(a);
            const std::size_t count = neighbours.count(a);
            r.resize(count);
            w.resize(count);
            dw.resize(count);
            for (std::size_t i = 0; i < count; ++i)
            {
                r[i] = (x[a] - x[neighbours.indices[first + i]]).norm();
            }
            kernel.evaluate(r.data(), count, w.data(), dw.data());
            for (std::size_t i = 0; i < count; ++i)
            {
                W[first + i] = w[i];
                // ∇W_ab = W'(r) (x_a - x_b)/r; zero for the particle itself.
                gradW[first + i] =
                    r[i] > 0.0 ? Vec<D>((dw[i] / r[i]) * (x[a] - x[neighbours.indices[first + i]]))
                               : Vec<D>::Zero();
            }
        }
    }
    return gradient.build(neighbours, x, V, gradW);
}

template struct ReferenceConfiguration<1>;
template struct ReferenceConfiguration<2>;
template struct ReferenceConfiguration<3>;

} // namespace sph
