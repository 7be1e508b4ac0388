#pragma once
// Third-order tensors and the monomial basis z_p(v) = v_j v_k (j <= k) of the gradient-of-F
// least squares (spec §6.2): from the fitted coefficients to H = ∇f, and the contraction of a
// third-order tensor with the monomials that the exact force needs.

#include "particles/Types.hpp"

namespace sph
{

// H from the least-squares coefficients c (½ H[v,v] = Σ_p c_p z_p(v)):
// H_ijj = 2 c_i(jj), H_ijk = H_ikj = c_i(jk) for j < k (spec §6.2).
template <int D, class MatDM>
Tensor3<D> hessianFromCoefficients(const MatDM& c)
{
    Tensor3<D> H = Tensor3<D>::zero();
    int p = 0;
    for (int j = 0; j < D; ++j)
    {
        for (int k = j; k < D; ++k, ++p)
        {
            if (j == k)
            {
                for (int i = 0; i < D; ++i)
                {
                    H(i, j, j) = 2.0 * c(i, p);
                }
            }
            else
            {
                for (int i = 0; i < D; ++i)
                {
                    H(i, j, k) = c(i, p);
                    H(i, k, j) = c(i, p);
                }
            }
        }
    }
    return H;
}

// B~_ip: 2 B_imm for p = (m, m); B_imk + B_ikm for p = (m, k), m < k, with B_imk = B[k](i, m).
template <int D, class MatDM>
MatDM contractMonomials(const Tensor3<D>& B)
{
    MatDM Bt;
    int p = 0;
    for (int m = 0; m < D; ++m)
    {
        for (int k = m; k < D; ++k, ++p)
        {
            if (m == k)
            {
                Bt.col(p) = 2.0 * B.slice[static_cast<std::size_t>(m)].col(m);
            }
            else
            {
                Bt.col(p) = B.slice[static_cast<std::size_t>(k)].col(m) +
                            B.slice[static_cast<std::size_t>(m)].col(k);
            }
        }
    }
    return Bt;
}

} // namespace sph
