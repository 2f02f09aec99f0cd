// Forms a family's dense local tangent matrix from the factored tangent of the kernel ABI.
#pragma once

#include <vector>

#include "kernel_abi.hpp"

namespace pd {

// M = d f / d y for the family's particles 0..L, row-major, size n = (L+1)*dim.
// With c_i = V0*V_i, f_0 = sum_i c_i t_i and f_{i+1} = -c_i t_i (kernel_abi.hpp),
// and T_ik = d t_i / d Y_k:
//   M[i+1][k+1] = -c_i T_ik       M[i+1][0] =  c_i sum_k T_ik
//   M[0][k+1]   = sum_i c_i T_ik   M[0][0]   = -sum_i c_i sum_k T_ik
// Cost O(L^2 dim^2 n_states): the price of an explicit matrix; the JVP kernel is O(L).
inline void form_local_matrix(int dim, int n_states, const abi::Family& fam,
                              const abi::TangentFactors& fac, double* M) {
  const int L = fam.n_bonds;
  const int n = (L + 1) * dim;
  for (int a = 0; a < n * n; ++a) M[a] = 0.0;
  const int dd = dim * dim;
  double T[9];
  for (int i = 0; i < L; ++i) {
    const double c = fam.V0 * fam.V[i];
    const double* left_i = fac.left + static_cast<std::ptrdiff_t>(i) * n_states * dim;
    for (int k = 0; k < L; ++k) {
      const double* right_k = fac.right + static_cast<std::ptrdiff_t>(k) * n_states * dim;
      for (int a = 0; a < dd; ++a) T[a] = (i == k) ? fac.direct[i * dd + a] : 0.0;
      for (int s = 0; s < n_states; ++s)
        for (int r = 0; r < dim; ++r)
          for (int q = 0; q < dim; ++q) T[r * dim + q] += left_i[s * dim + r] * right_k[s * dim + q];
      for (int r = 0; r < dim; ++r) {
        for (int q = 0; q < dim; ++q) {
          const double v = c * T[r * dim + q];
          const int row_i = (i + 1) * dim + r, col_k = (k + 1) * dim + q;
          M[row_i * n + col_k] -= v;
          M[row_i * n + q] += v;
          M[r * n + col_k] += v;
          M[r * n + q] -= v;
        }
      }
    }
  }
}

// Scratch storage for one family's tangent factors, sized once per thread.
struct TangentScratch {
  std::vector<double> direct, left, right;
  abi::TangentFactors view(int dim, int n_states, int L) {
    direct.resize(static_cast<std::size_t>(L) * dim * dim);
    left.resize(static_cast<std::size_t>(L) * n_states * dim);
    right.resize(static_cast<std::size_t>(L) * n_states * dim);
    return {direct.data(), left.data(), right.data()};
  }
};

}  // namespace pd
