// Two-horizon sparsity pattern, built with a marker array per column.
#include "assemble/sparsity.hpp"

#include <algorithm>
#include <stdexcept>

namespace pd {

Sparsity::Sparsity(const Bonds& bonds, int dim) : n_(bonds.particle_count()), dim_(dim) {
  // Column b couples to every particle of every family containing b: the families of
  // b and of its neighbours (bonds are stored in both directions).
  std::vector<int> mark(static_cast<std::size_t>(n_), -1), col;
  col_start_.assign(static_cast<std::size_t>(n_) + 1, 0);
  for (int b = 0; b < n_; ++b) {
    col.clear();
    auto add_family = [&](int p) {
      if (mark[p] != b) mark[p] = b, col.push_back(p);
      for (int e = bonds.offsets[p]; e < bonds.offsets[p + 1]; ++e) {
        const int q = bonds.neighbor[e];
        if (mark[q] != b) mark[q] = b, col.push_back(q);
      }
    };
    add_family(b);
    for (int e = bonds.offsets[b]; e < bonds.offsets[b + 1]; ++e) add_family(bonds.neighbor[e]);
    std::sort(col.begin(), col.end());
    rows_.insert(rows_.end(), col.begin(), col.end());
    col_start_[b + 1] = static_cast<int>(rows_.size());
  }
  if (static_cast<long long>(rows_.size()) * dim * dim > 2000000000LL)
    throw std::runtime_error("the stiffness matrix would exceed 2e9 nonzeros: use the matrix-free solver");
}

SparseMatrix Sparsity::zero_matrix() const {
  const int N = n_ * dim_;
  SparseMatrix K(N, N);
  K.resizeNonZeros(static_cast<Eigen::Index>(nonzeros()));
  int* outer = K.outerIndexPtr();
  int* inner = K.innerIndexPtr();
  double* values = K.valuePtr();
  int pos = 0;
  for (int b = 0; b < n_; ++b)
    for (int q = 0; q < dim_; ++q) {
      outer[b * dim_ + q] = pos;
      for (int e = col_start_[b]; e < col_start_[b + 1]; ++e)
        for (int r = 0; r < dim_; ++r) {
          inner[pos] = rows_[e] * dim_ + r;
          values[pos] = 0.0;
          ++pos;
        }
    }
  outer[N] = pos;
  return K;
}

int Sparsity::slot(int a, int b, int r, int q) const {
  const auto first = rows_.begin() + col_start_[b], last = rows_.begin() + col_start_[b + 1];
  const auto it = std::lower_bound(first, last, a);
  const int len = col_start_[b + 1] - col_start_[b];
  // Column b*dim+q starts at (col_start_[b]*dim + q*len) * dim in the value array.
  return (col_start_[b] * dim_ + q * len) * dim_ + static_cast<int>(it - first) * dim_ + r;
}

}  // namespace pd
