// Writes one family's dense local tangent into the global stiffness's value array.
#pragma once

#include <cstddef>

#include "assembly/sparsity_pattern.hpp"

namespace pd {

// M: the family's dense local tangent d f / d y, row-major, (L+1)*D square
// (local_matrix.hpp); slots: the family's block bases (SparsityPattern::family_slots, in
// the layout of its coupling); strides[a]: column_stride of local particle a. Subtracts
// M from the values (K = -df/du, the solver's sign).
//
// The index arithmetic is per block: one slot and one stride give the block's D columns
// of D contiguous values, and with D fixed at compile time the block's D^2 updates
// unroll into straight-line code. Blocks are visited a particle column at a time, so the
// writes of one column stay within its few kilobytes of K.
template <int D>
void scatter_block(const double* __restrict M, std::ptrdiff_t m, int a, int b, int base, int stride,
                   double* __restrict values) {
  const double* src = M + static_cast<std::ptrdiff_t>(a) * D * m + static_cast<std::ptrdiff_t>(b) * D;
  for (int q = 0; q < D; ++q) {
    double* __restrict col = values + base + static_cast<std::ptrdiff_t>(q) * stride;
    for (int r = 0; r < D; ++r) col[r] -= src[r * m + q];
  }
}

template <int D>
void scatter_family(Coupling coupling, const double* __restrict M, int L, const int* __restrict slots,
                    const int* __restrict strides, double* __restrict values) {
  const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(L + 1) * D;
  if (coupling == Coupling::family) {
    for (int b = 0; b <= L; ++b) {
      const int* column_slots = slots + static_cast<std::ptrdiff_t>(b) * (L + 1);
      for (int a = 0; a <= L; ++a) scatter_block<D>(M, m, a, b, column_slots[a], strides[b], values);
    }
    return;
  }
  // Pairwise: the center's column, then each neighbour's two blocks (the center's row
  // and its own diagonal); the neighbour-neighbour blocks of M are zero and skipped.
  for (int a = 0; a <= L; ++a) scatter_block<D>(M, m, a, 0, slots[a], strides[0], values);
  for (int k = 1; k <= L; ++k) {
    scatter_block<D>(M, m, 0, k, slots[L + 2 * k - 1], strides[k], values);
    scatter_block<D>(M, m, k, k, slots[L + 2 * k], strides[k], values);
  }
}

// A law without states, pairwise pattern: from the (L+1) blocks of form_pair_blocks
// (local_matrix.hpp: M[0][0] = B[0], M[0][k] = M[k][0] = B[k], M[k][k] = -B[k], each
// row-major) instead of the dense matrix, whose other blocks are zero.
template <int D>
void scatter_pair_blocks(const double* __restrict B, int L, const int* __restrict slots,
                         const int* __restrict strides, double* __restrict values) {
  auto add = [&](const double* blk, int base, int stride, double sign) {
    for (int q = 0; q < D; ++q)
      for (int r = 0; r < D; ++r) values[base + q * stride + r] -= sign * blk[r * D + q];
  };
  add(B, slots[0], strides[0], 1.0);
  for (int k = 1; k <= L; ++k) {
    const double* blk = B + static_cast<std::ptrdiff_t>(k) * D * D;
    add(blk, slots[k], strides[0], 1.0);
    add(blk, slots[L + 2 * k - 1], strides[k], 1.0);
    add(blk, slots[L + 2 * k], strides[k], -1.0);
  }
}

inline void scatter_pair_blocks(int dim, const double* B, int L, const int* slots, const int* strides,
                                double* values) {
  if (dim == 2) return scatter_pair_blocks<2>(B, L, slots, strides, values);
  if (dim == 3) return scatter_pair_blocks<3>(B, L, slots, strides, values);
  scatter_pair_blocks<1>(B, L, slots, strides, values);
}

inline void scatter_family(int dim, Coupling coupling, const double* M, int L, const int* slots,
                           const int* strides, double* values) {
  if (dim == 2) return scatter_family<2>(coupling, M, L, slots, strides, values);
  if (dim == 3) return scatter_family<3>(coupling, M, L, slots, strides, values);
  scatter_family<1>(coupling, M, L, slots, strides, values);  // the laws are 2D or 3D; 1D for completeness
}

}  // namespace pd
