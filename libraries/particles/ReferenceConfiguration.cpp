#include "particles/Parallel.hpp"
#include "particles/ReferenceConfiguration.hpp"

#include "particles/Parallel.hpp"

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
                                        double radius, bool reuseCandidates, bool keepKernelValues)
{
    searchRadius = radius;
    if (!reuseCandidates)
    {
        neighbours = buildNeighbourList<D>(x, body, radius);
        candidates.clear();
    }
    else
    {
        candidates.update(x, body, radius, neighbours);
    }
    const std::size_t pairs = neighbours.pairCount();
    if (keepKernelValues)
    {
        resizePairArray(W, pairs);
    }
    else
    {
        W.clear();
        W.shrink_to_fit();
    }
    resizePairArray(dWdrOverR, pairs);
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
                if (keepKernelValues)
                {
                    W[first + i] = w[i];
                }
                // ∇W_ab = W'(r) (x_a - x_b)/r; zero for the particle itself.
                dWdrOverR[first + i] = r[i] > 0.0 ? dw[i] / r[i] : 0.0;
            }
        }
    }
    return gradient.build(neighbours, x, V,
                          [this](std::size_t a, std::size_t k) { return gradW(a, k); }, owned);
}

template struct ReferenceConfiguration<1>;
template struct ReferenceConfiguration<2>;
template struct ReferenceConfiguration<3>;

} // namespace sph
