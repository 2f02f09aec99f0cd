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

// Particle a couples to particle b when some family holds both (two-horizon reach):
// the pattern is the union of every family's (L+1)^2 particle blocks, each a dense
// dim x dim block. Entries of particle column b are stored for each of its dim
// columns with the same particle rows in ascending order, so block (a, b) entry
// (r, q) is at  base(a, b) + q * column_stride(b) + r.
//
// Slots: for every family p, base(a, b) for its local particles a, b in 0..L (0 the
// center, k+1 for bond k), row-major [a*(L+1) + b]. One int per block instead of one
// per entry keeps the table at (L+1)^2 ints per family: 5.8 kB per family at 37
// bonds, below the matrix itself (about 150 blocks of 4 doubles per particle column).
class SparsityPattern {
 public:
  // Builds the pattern and the slots once. Throws if the value array would not be
  // addressable with 32-bit indices (then use the matrix-free path).
  SparsityPattern(const Bonds& bonds, int dim);

  // A matrix with this pattern and zero values.
  SparseMatrix matrix() const;
  int dim() const { return dim_; }
  int particles() const { return n_; }
  std::int64_t nonzeros() const { return static_cast<std::int64_t>(rows_.size()) * dim_ * dim_; }
  // Particle rows of particle column b, ascending.
  std::span<const int> column(int b) const {
    return {rows_.data() + col_start_[b], static_cast<std::size_t>(col_start_[b + 1] - col_start_[b])};
  }
  int column_stride(int b) const { return (col_start_[b + 1] - col_start_[b]) * dim_; }
  // Block bases of family p, [(L+1)^2], row-major in the local particle indices.
  std::span<const int> family_slots(int p) const {
    return {slots_.data() + slot_start_[p], static_cast<std::size_t>(slot_start_[p + 1] - slot_start_[p])};
  }
  // Base of block (a, b) by search, for tests and the rare caller without a family.
  int block_base(int a, int b) const;

 private:
  int n_, dim_;
  std::vector<int> col_start_;         // [n+1] range of particle column b in rows_
  std::vector<int> rows_;              // particle rows per particle column
  std::vector<std::int64_t> slot_start_;  // [n+1] range of family p in slots_
  std::vector<int> slots_;             // block bases per family
};

}  // namespace pd
