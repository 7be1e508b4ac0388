#pragma once
// Fixed-size linear algebra for the dimension-templated code (Dim = 1, 2, 3).
// Conventions follow spec §0: (u ⊗ v)_ij = u_i v_j; third-order tensors keep the derivative
// index last, (∇F)_ijk = ∂F_ij/∂x_k, and are stored as D matrices sliced by that index.

#include <Eigen/Core>
#include <Eigen/LU>

#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace sph
{

template <int D>
using Vec = Eigen::Matrix<double, D, 1>;

template <int D>
using Mat = Eigen::Matrix<double, D, D>;

// x^(1/D) for x >= 0: a length from a D-dimensional volume, a stretch from a volume ratio.
template <int D>
inline double rootOfDimension(double x)
{
    if constexpr (D == 1)
    {
        return x;
    }
    else if constexpr (D == 2)
    {
        return std::sqrt(x);
    }
    else
    {
        return std::cbrt(x);
    }
}

// Number of distinct second-order monomials v_j v_k (j <= k): 1, 3, 6.
template <int D>
inline constexpr int monomialCount = D * (D + 1) / 2;

template <int D>
using MonomialVec = Eigen::Matrix<double, monomialCount<D>, 1>;

// A third-order tensor T_ijk, stored as slices T[k](i, j) along the last (derivative) index.
template <int D>
struct Tensor3
{
    std::array<Mat<D>, D> slice;

    static Tensor3 zero()
    {
        Tensor3 t;
        for (auto& s : t.slice)
        {
            s.setZero();
        }
        return t;
    }
    // (T v)_ij = T_ijk v_k
    Mat<D> contract(const Vec<D>& v) const
    {
        Mat<D> result = slice[0] * v[0];
        for (int k = 1; k < D; ++k)
        {
            result += slice[static_cast<std::size_t>(k)] * v[k];
        }
        return result;
    }
    double operator()(int i, int j, int k) const { return slice[static_cast<std::size_t>(k)](i, j); }
    double& operator()(int i, int j, int k) { return slice[static_cast<std::size_t>(k)](i, j); }
};

template <int D>
Vec<D> toVec(const std::vector<double>& values)
{
    if (static_cast<int>(values.size()) != D)
    {
        throw std::logic_error("vector of " + std::to_string(values.size()) +
                               " components where " + std::to_string(D) + " were expected");
    }
    Vec<D> v;
    for (int i = 0; i < D; ++i)
    {
        v[i] = values[static_cast<std::size_t>(i)];
    }
    return v;
}

// Monomials z_p(v) = v_j v_k for p = (j, k), j <= k, in the order (0,0), (0,1), .., (1,1), ..
template <int D>
MonomialVec<D> monomials(const Vec<D>& v)
{
    MonomialVec<D> z;
    int p = 0;
    for (int j = 0; j < D; ++j)
    {
        for (int k = j; k < D; ++k)
        {
            z[p++] = v[j] * v[k];
        }
    }
    return z;
}

// Embeds a D-vector / D×D matrix into 3D (zeros elsewhere; matrices get 1 on the missing
// diagonal when `identityPadding`, e.g. F in plane strain).
template <int D>
Eigen::Vector3d embed(const Vec<D>& v)
{
    Eigen::Vector3d out = Eigen::Vector3d::Zero();
    out.head<D>() = v;
    return out;
}

template <int D>
Eigen::Matrix3d embed(const Mat<D>& m, bool identityPadding)
{
    Eigen::Matrix3d out = Eigen::Matrix3d::Zero();
    if (identityPadding)
    {
        out.setIdentity();
    }
    out.topLeftCorner<D, D>() = m;
    return out;
}

} // namespace sph
