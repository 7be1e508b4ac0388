#include "particles/Parallel.hpp"
#include "particles/ReferenceConfiguration.hpp"

#include "particles/Parallel.hpp"

#include <atomic>
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
    kernel_ = &kernel;
    keepsW_ = keepKernelValues;
    static std::atomic<std::uint64_t> versions{0};
    version_ = ++versions; // the recomputed values of an earlier rebuild are stale
    if (recomputeKernelValues)
    {
        W = {};
        dWdrOverR = {};
    }
    else
    {
        storeKernelValues(keepKernelValues);
    }
    return gradient.build(
        neighbours, x, V,
        [this](std::size_t a) {
            const double* dwr = kernelValues(a).dWdrOverR;
            return [this, a, dwr](std::size_t k) { return gradW(a, k, dwr); };
        },
        owned);
}

template <int D>
void ReferenceConfiguration<D>::storeKernelValues(bool withW)
{
    if (withW)
    {
        resizePairArray(W, neighbours.pairCount());
    }
    else
    {
        W = {};
    }
    resizePairArray(dWdrOverR, neighbours.pairCount());
    const std::size_t n = size();
#pragma omp parallel if (useThreads(n))
    {
        PairBuffers values;
#pragma omp for schedule(static)
        for (std::size_t a = 0; a < n; ++a)
        {
            evaluatePairs(a, values);
            const std::size_t first = neighbours.begin(a);
            if (withW)
            {
                std::copy(values.w.begin(), values.w.end(), W.begin() + static_cast<long>(first));
            }
            std::copy(values.dwr.begin(), values.dwr.end(),
                      dWdrOverR.begin() + static_cast<long>(first));
        }
    }
}

template <int D>
void ReferenceConfiguration<D>::evaluatePairs(std::size_t a, PairBuffers& values) const
{
    const std::size_t first = neighbours.begin(a);
    const std::size_t count = neighbours.count(a);
    values.r.resize(count);
    values.w.resize(count);
    values.dwr.resize(count);
    for (std::size_t i = 0; i < count; ++i)
    {
        values.r[i] = (x[a] - x[neighbours.indices[first + i]]).norm();
    }
    kernel_->evaluate(values.r.data(), count, values.w.data(), values.dwr.data());
    for (std::size_t i = 0; i < count; ++i)
    {
        // ∇W_ab = W'(r) (x_a - x_b)/r; zero for the particle itself.
        values.dwr[i] = values.r[i] > 0.0 ? values.dwr[i] / values.r[i] : 0.0;
    }
}

// One buffer per thread, holding the particle it was last asked for: the loops ask for one
// particle's pairs at a time, each of them several times in a row.
template <int D>
typename ReferenceConfiguration<D>::PairKernelValues
ReferenceConfiguration<D>::recomputedKernelValues(std::size_t a) const
{
    struct Held
    {
        std::uint64_t version = 0;
        std::size_t particle = 0;
        PairBuffers values;
    };
    thread_local Held held;
    if (held.version != version_ || held.particle != a)
    {
        evaluatePairs(a, held.values);
        held.version = version_;
        held.particle = a;
    }
    return {keepsW_ ? held.values.w.data() : nullptr, held.values.dwr.data()};
}

template struct ReferenceConfiguration<1>;
template struct ReferenceConfiguration<2>;
template struct ReferenceConfiguration<3>;

} // namespace sph
