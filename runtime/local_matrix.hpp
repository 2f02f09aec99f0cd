// Forms a family's dense local tangent matrix from the factored tangent of the kernel ABI.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "kernel_abi.hpp"

namespace pd {

// M = d f / d y for the family's particles 0..L, row-major, size n = (L+1)*dim.
// With c_i = V0*V_i, f_0 = sum_i c_i t_i and f_{i+1} = -c_i t_i (kernel_abi.hpp),
// and T_ik = d t_i / d Y_k = delta_ik direct_i + sum_s left_i[s] (x) right_k[s]:
//   M[i+1][k+1] = -c_i T_ik       M[i+1][0] =  c_i sum_k T_ik
//   M[0][k+1]   = sum_i c_i T_ik   M[0][0]   = -sum_i c_i sum_k T_ik
// The neighbour block is a rank-n_states product written row by row (contiguous
// stores); the center row and column use the sums over k of right_k and over i of
// c_i left_i, so only the neighbour block costs O(L^2).
//
// DIM and STATES > 0 fix the dimension and state count at compile time (the loops over
// them unroll: 3x faster for correspondence's 4 states); 0 reads them at run time.
template <int DIM, int STATES>
void form_local_matrix_for(int dim, int n_states, const abi::Family& fam, const abi::TangentFactors& fac,
                           double* M) {
  const int L = fam.n_bonds, d = DIM > 0 ? DIM : dim, S = STATES > 0 ? STATES : n_states;
  const int n = (L + 1) * d, dd = d * d;
  double right_sum[3 * 16] = {}, left_sum[3 * 16] = {};  // [s*d + q], n_states <= 16 on the stack
  std::vector<double> heap;
  double* rs = right_sum;
  double* ls = left_sum;
  if (S > 16) {
    heap.assign(static_cast<std::size_t>(2 * S * d), 0.0);
    rs = heap.data();
    ls = heap.data() + S * d;
  }
  for (int k = 0; k < L; ++k) {
    const double c = fam.V0 * fam.V[k];
    for (int a = 0; a < S * d; ++a) {
      rs[a] += fac.right[k * S * d + a];
      ls[a] += c * fac.left[k * S * d + a];
    }
  }
  double center[9] = {};
  for (int i = 0; i < L; ++i) {
    const double c = fam.V0 * fam.V[i];
    const double* left_i = fac.left + static_cast<std::ptrdiff_t>(i) * S * d;
    const double* direct_i = fac.direct + static_cast<std::ptrdiff_t>(i) * dd;
    for (int r = 0; r < d; ++r) {
      double* row = M + static_cast<std::ptrdiff_t>((i + 1) * d + r) * n;
      // Neighbour block row: -c_i sum_s left_i[s][r] right_k[s][q], plus the direct term at k = i.
      double* __restrict block = row + d;
      if (S == 0)
        for (int col = 0; col < n - d; ++col) block[col] = 0.0;
      if (S == 1) {  // the common case: one contiguous scaled copy
        const double a = -c * left_i[r];
        const double* __restrict right = fac.right;
        for (int col = 0; col < n - d; ++col) block[col] = a * right[col];
      } else if (S > 1) {
        // Entry by entry with the state sum innermost: one store per entry and each
        // bond's right factors read contiguously. One read-modify-write pass over the
        // row per state instead made correspondence's dense tangent 5x slower.
        double a_stack[16];
        std::vector<double> a_heap;
        double* a = a_stack;
        if (S > 16) a_heap.resize(static_cast<std::size_t>(S)), a = a_heap.data();
        for (int s = 0; s < S; ++s) a[s] = -c * left_i[s * d + r];
        for (int k = 0; k < L; ++k) {
          const double* __restrict rk = fac.right + static_cast<std::ptrdiff_t>(k) * S * d;
          for (int q = 0; q < d; ++q) {
            double v = 0.0;
            for (int s = 0; s < S; ++s) v += a[s] * rk[s * d + q];
            block[k * d + q] = v;
          }
        }
      }
      for (int q = 0; q < d; ++q) row[(i + 1) * d + q] -= c * direct_i[r * d + q];
      // Center column: c_i (direct_i + sum_s left_i[s] (x) sum_k right_k[s]).
      for (int q = 0; q < d; ++q) {
        double v = direct_i[r * d + q];
        for (int s = 0; s < S; ++s) v += left_i[s * d + r] * rs[s * d + q];
        row[q] = c * v;
        center[r * d + q] -= c * v;
      }
    }
  }
  // Center row: c_k direct_k + sum_s (sum_i c_i left_i[s]) (x) right_k[s]; M[0][0] = -sum_i c_i sum_k T_ik.
  for (int r = 0; r < d; ++r) {
    double* row = M + static_cast<std::ptrdiff_t>(r) * n;
    for (int q = 0; q < d; ++q) row[q] = center[r * d + q];
    for (int k = 0; k < L; ++k) {
      const double c = fam.V0 * fam.V[k];
      for (int q = 0; q < d; ++q) {
        double v = c * fac.direct[k * dd + r * d + q];
        for (int s = 0; s < S; ++s) v += ls[s * d + r] * fac.right[(k * S + s) * d + q];
        row[(k + 1) * d + q] = v;
      }
    }
  }
}

inline void form_local_matrix(int dim, int n_states, const abi::Family& fam, const abi::TangentFactors& fac,
                              double* M) {
  if (dim == 2 && n_states == 1) return form_local_matrix_for<2, 1>(dim, n_states, fam, fac, M);
  if (dim == 3 && n_states == 1) return form_local_matrix_for<3, 1>(dim, n_states, fam, fac, M);
  if (dim == 2 && n_states == 4) return form_local_matrix_for<2, 4>(dim, n_states, fam, fac, M);
  if (dim == 3 && n_states == 9) return form_local_matrix_for<3, 9>(dim, n_states, fam, fac, M);
  form_local_matrix_for<0, 0>(dim, n_states, fam, fac, M);
}

// The same matrix through the law's generated form kernel (KernelVariant::form: the
// structural zeros of the law's factors skipped) when it has one, else the generic forming.
inline void form_local_matrix(const abi::KernelVariant& variant, int dim, int n_states,
                              const abi::Family& fam, const abi::TangentFactors& fac, double* M) {
  if (variant.form != nullptr) return variant.form(fam, fac, M);
  form_local_matrix(dim, n_states, fam, fac, M);
}

// A law without states (bond-based: n_states == 0) has T_ik = delta_ik direct_i, so its
// local matrix has only the blocks of bond k with itself and with the center:
//   M[0][k+1] = M[k+1][0] = B[k+1],  M[k+1][k+1] = -B[k+1],  M[0][0] = B[0],
// B[k+1] = c_k direct_k, B[0] = -sum_k B[k+1]; every other block is zero. Writes the
// (L+1) d x d blocks B, row-major each, [(L+1)*dim*dim] in all: what a one-horizon
// scatter needs instead of the (L+1)^2 d^2 dense matrix.
inline void form_pair_blocks(int dim, const abi::Family& fam, const abi::TangentFactors& fac, double* B) {
  const int L = fam.n_bonds, dd = dim * dim;
  for (int a = 0; a < dd; ++a) B[a] = 0.0;
  for (int k = 0; k < L; ++k) {
    const double c = fam.V0 * fam.V[k];
    double* __restrict b = B + static_cast<std::ptrdiff_t>(k + 1) * dd;
    for (int a = 0; a < dd; ++a) {
      b[a] = c * fac.direct[k * dd + a];
      B[a] -= b[a];
    }
  }
}

// True when the factors are finite and small enough that every entry of the local
// matrix formed from them is finite too: O(L) work instead of a pass over the O(L^2)
// matrix. Each entry is a sum of at most L (direct + S L left right) terms scaled by
// some c_i = V0 V_i (the center block's is the largest), so with the largest magnitudes
// of the factors the bound L c (D + L S l r) stays below DBL_MAX with room to spare.
inline bool factors_finite(int dim, int n_states, const abi::Family& fam, const abi::TangentFactors& fac) {
  const int L = fam.n_bonds, dd = dim * dim, sd = n_states * dim;
  double nan_sum = 0.0, c_max = 0.0, d_max = 0.0, l_max = 0.0, r_max = 0.0;
  for (int k = 0; k < L; ++k) {
    const double c = fam.V0 * fam.V[k];
    nan_sum += c * 0.0;
    c_max = std::max(c_max, std::abs(c));
    for (int a = 0; a < dd; ++a) {
      nan_sum += fac.direct[k * dd + a] * 0.0;  // 0 for finite values, NaN for NaN and Inf
      d_max = std::max(d_max, std::abs(fac.direct[k * dd + a]));
    }
    for (int a = 0; a < sd; ++a) {
      nan_sum += (fac.left[k * sd + a] + fac.right[k * sd + a]) * 0.0;
      l_max = std::max(l_max, std::abs(fac.left[k * sd + a]));
      r_max = std::max(r_max, std::abs(fac.right[k * sd + a]));
    }
  }
  if (nan_sum != 0.0) return false;
  const double n = L, bound = n * c_max * (d_max + n * n_states * l_max * r_max);
  return bound < std::numeric_limits<double>::max() / 16;
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
