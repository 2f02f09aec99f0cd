// The sparsity of the global stiffness: particle a couples to particle b when some
// family holds both (two-horizon reach). Built once; stored compressed by column
// with every particle pair a dim x dim dense block, so a block's entries are found
// from one binary search.
#pragma once

#include <Eigen/Sparse>
#include <vector>

#include "particles.hpp"

namespace pd {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

class Sparsity {
 public:
  Sparsity(const Bonds& bonds, int dim);
  // A matrix with this pattern and zero values.
  SparseMatrix zero_matrix() const;
  // Index into the value array of entry (a*dim + r, b*dim + q).
  int slot(int a, int b, int r, int q) const;
  int particles() const { return n_; }
  long long nonzeros() const { return static_cast<long long>(rows_.size()) * dim_ * dim_; }

 private:
  int n_, dim_;
  std::vector<int> col_start_;  // [n+1] per particle column: range into rows_
  std::vector<int> rows_;       // particle rows of each particle column, ascending
};

}  // namespace pd
