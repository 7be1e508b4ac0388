#pragma once
// The principal form of N symmetric 3×3 matrices side by side (ReturnLanes.hpp): cyclic Jacobi
// rotations lane by lane (Golub & Van Loan, Matrix Computations, §8.5). Near the identity, as
// the elastic be of a plastic material is, two to four sweeps reach every digit; unlike the
// closed form of the characteristic cubic, the rotations keep every digit at a double
// eigenvalue (uniaxial states have one). A lane that has converged is left alone to the bit,
// so that a matrix gives the same digits in any batch.

#include "materials/plasticity/ReturnLanes.hpp"

#include <cmath>

namespace sph
{

namespace lanes
{

// The index of (i, j) in a symmetric 3×3 stored as (00, 11, 22, 01, 02, 12).
constexpr int symmetric(int i, int j)
{
    return i == j ? i : (i + j == 1 ? 3 : (i + j == 2 ? 4 : 5));
}

// One Jacobi rotation in the (p, q) plane that zeroes a_pq, lane by lane (Golub & Van Loan
// §8.5: t = sgn θ/(|θ| + √(θ² + 1)), θ = (a_qq − a_pp)/(2 a_pq); t = 0 where a_pq = 0).
template <int N, int p, int q>
inline void rotate(Lane<N> (&a)[6], Lane<N> (&v)[3][3], const Lane<N>& done)
{
    constexpr int r = 3 - p - q;
    constexpr int pq = symmetric(p, q);
    constexpr int rp = symmetric(r, p);
    constexpr int rq = symmetric(r, q);
    for (int i = 0; i < N; ++i)
    {
        const double x = a[pq][i];
        const double theta = (a[q][i] - a[p][i]) / (2.0 * x);
        const double rotation =
            std::copysign(1.0, theta) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        // A lane already converged (done ≠ 0) stays as it is to the bit: t = 0 and a_pq kept,
        // so that a point gives the same digits in any batch (one lane or sixteen).
        const bool keep = x == 0.0 || done[i] != 0.0;
        const double t = keep ? 0.0 : rotation;
        const double c = 1.0 / std::sqrt(t * t + 1.0);
        const double s = t * c;
        a[p][i] -= t * x;
        a[q][i] += t * x;
        a[pq][i] = keep ? x : 0.0;
        const double arp = a[rp][i];
        const double arq = a[rq][i];
        a[rp][i] = c * arp - s * arq;
        a[rq][i] = s * arp + c * arq;
        for (int k = 0; k < 3; ++k)
        {
            const double vp = v[k][p][i];
            const double vq = v[k][q][i];
            v[k][p][i] = c * vp - s * vq;
            v[k][q][i] = s * vp + c * vq;
        }
    }
}

// The principal form of N symmetric 3×3 matrices a = (00, 11, 22, 01, 02, 12): sweeps of
// rotations until every lane's off-diagonal part is below 1e-17 of its diagonal (near the
// identity, as be is, two to four sweeps); a lane that has converged is left alone.
template <int N>
void principalForm(Lane<N> (&matrix)[6], Lane<N> (&vectors)[3][3])
{
    // Local copies: the rotations vectorise only where the compiler sees that the matrix and
    // the vectors cannot overlap.
    Lane<N> a[6];
    Lane<N> v[3][3];
    for (int k = 0; k < 6; ++k)
    {
        a[k] = matrix[k];
    }
    for (int i = 0; i < 3; ++i)
    {
        for (int k = 0; k < 3; ++k)
        {
            v[i][k] = Lane<N>::Constant(i == k ? 1.0 : 0.0);
        }
    }
    for (int sweep = 0; sweep < 16; ++sweep)
    {
        Lane<N> done;
        for (int i = 0; i < N; ++i)
        {
            const double off = a[3][i] * a[3][i] + a[4][i] * a[4][i] + a[5][i] * a[5][i];
            const double diagonal = a[0][i] * a[0][i] + a[1][i] * a[1][i] + a[2][i] * a[2][i];
            done[i] = off > 1e-34 * diagonal ? 0.0 : 1.0;
        }
        if (countLanes<N>([&](int i) { return done[i] == 0.0; }) == 0)
        {
            break;
        }
        rotate<N, 0, 1>(a, v, done);
        rotate<N, 0, 2>(a, v, done);
        rotate<N, 1, 2>(a, v, done);
    }
    for (int k = 0; k < 6; ++k)
    {
        matrix[k] = a[k];
    }
    for (int i = 0; i < 3; ++i)
    {
        for (int k = 0; k < 3; ++k)
        {
            vectors[i][k] = v[i][k];
        }
    }
}

} // namespace lanes

} // namespace sph
