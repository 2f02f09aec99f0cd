// The pattern of the global stiffness and every family's slots in its value array.
#pragma once

#include <Eigen/Sparse>
#include <cstdint>
#include <span>
#include <vector>

#include "particles.hpp"

namespace pd {

// Column-major, compressed, 32-bit indices: what Eigen's CHOLMOD/UMFPACK wrappers and
// iterative solvers take without a copy.
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// Which particles a family's tangent couples.
//   family:   every two members (a law with states: bond i's force depends on bond k
//             through the states), so particles two horizons apart share entries;
//   pairwise: the center with each neighbour only (a law without states: T_ik = 0 for
//             i != k, kernel_abi.hpp), so the reach is one horizon and a 2D lattice at
//             delta/h = 3.5 has about a quarter of the family coupling's nonzeros.
enum class Coupling { family, pairwise };
inline Coupling coupling_of_law(int n_states) {
  return n_states == 0 ? Coupling::pairwise : Coupling::family;
}

// The pattern is the union of every family's coupled particle blocks, each a dense
// dim x dim block. Entries of particle column b are stored for each of its dim
// columns with the same particle rows in ascending order, so block (a, b) entry
// (r, q) is at  base(a, b) + q * column_stride(b) + r.
//
// Slots: for every family p, base(a, b) of the blocks it writes, in local particle
// indices a, b (0 the center, k+1 for bond k). One int per block, not per entry.
//   family:   (L+1)^2 slots, column-major: block (a, b) at [b*(L+1) + a] (the scatter
//             walks one particle column at a time: its entries are close in memory);
//   pairwise: 3L+1 slots: block (a, 0) at [a] for a = 0..L, then for k = 1..L
//             block (0, k) at [L + 2k - 1] and block (k, k) at [L + 2k].
class SparsityPattern {
 public:
  // Builds the pattern and the slots once. Throws if the value array would not be
  // addressable with 32-bit indices (then use the matrix-free path).
  SparsityPattern(const Bonds& bonds, int dim, Coupling coupling = Coupling::family);

  // A matrix with this pattern and zero values.
  SparseMatrix matrix() const;
  int dim() const { return dim_; }
  int particles() const { return n_; }
  Coupling coupling() const { return coupling_; }
  std::int64_t nonzeros() const { return static_cast<std::int64_t>(rows_.size()) * dim_ * dim_; }
  // Particle rows of particle column b, ascending.
  std::span<const int> column(int b) const {
    return {rows_.data() + col_start_[b], static_cast<std::size_t>(col_start_[b + 1] - col_start_[b])};
  }
  int column_stride(int b) const { return (col_start_[b + 1] - col_start_[b]) * dim_; }
  // Block bases of family p, in the layout of coupling() (header comment).
  std::span<const int> family_slots(int p) const {
    return {slots_.data() + slot_start_[p], static_cast<std::size_t>(slot_start_[p + 1] - slot_start_[p])};
  }
  static std::int64_t slot_count(Coupling coupling, int L) {
    return coupling == Coupling::family ? static_cast<std::int64_t>(L + 1) * (L + 1)
                                        : 3 * static_cast<std::int64_t>(L) + 1;
  }
  // Base of block (a, b) by search, for tests and the rare caller without a family.
  int block_base(int a, int b) const;

 private:
  int n_, dim_;
  Coupling coupling_;
  std::vector<int> col_start_;            // [n+1] range of particle column b in rows_
  std::vector<int> rows_;                 // particle rows per particle column
  std::vector<std::int64_t> slot_start_;  // [n+1] range of family p in slots_
  std::vector<int> slots_;                // block bases per family
};

}  // namespace pd
