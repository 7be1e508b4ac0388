#include "particles/Parallel.hpp"
#include "particles/CorrectedGradient.hpp"

#include <cmath>

namespace sph
{

template <int D>
long CorrectedGradient<D>::build(const NeighbourList& list, const std::vector<Vec<D>>& x,
                                 const std::vector<double>& V, const std::vector<Vec<D>>& d)
{
    const std::size_t n = list.particleCount();
    L.resize(n);
    e.resize(n);
    long singular = -1;
#pragma omp parallel for schedule(static) reduction(max : singular) if (useThreads(n))
    for (std::size_t a = 0; a < n; ++a)
    {
        Mat<D> M = Mat<D>::Zero();
        Vec<D> sum = Vec<D>::Zero();
        for (std::size_t k = list.begin(a) + 1; k < list.end(a); ++k)
        {
            const std::size_t b = list.indices[k];
            const Vec<D> weighted = V[b] * d[k];
            M.noalias() += (x[b] - x[a]) * weighted.transpose();
            sum += weighted;
        }
        // M ≈ I on a regular cloud; a (near-)singular M means too few neighbours or all on a
        // line/plane: the gradient cannot be corrected there.
        const double det = M.determinant();
        if (!(std::abs(det) > 1.0e-8) || !std::isfinite(det))
        {
            singular = std::max<long>(singular, static_cast<long>(n - a)); // max → smallest a
            L[a].setIdentity();
        }
        else
        {
            L[a] = M.inverse().transpose();
        }
        e[a] = -sum;
    }
    return singular < 0 ? -1 : static_cast<long>(n) - singular;
}

template struct CorrectedGradient<1>;
template struct CorrectedGradient<2>;
template struct CorrectedGradient<3>;

} // namespace sph
