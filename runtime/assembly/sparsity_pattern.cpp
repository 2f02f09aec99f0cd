// The coupled particle pairs from the transposed family lists; slots by binary search, once.
#include "assembly/sparsity_pattern.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace pd {

namespace {
// members[p] = {p} + neighbours of p: the particles of family p.
template <class F>
void for_each_member(const Bonds& B, int p, F&& f) {
  f(p);
  for (int e = B.offsets[p]; e < B.offsets[p + 1]; ++e) f(B.neighbor[e]);
}
}  // namespace

SparsityPattern::SparsityPattern(const Bonds& B, int dim, Coupling coupling)
    : n_(B.particle_count()), dim_(dim), coupling_(coupling) {
  // Families containing each particle (the transpose of the membership lists). Bonds
  // are normally stored in both directions, but the transpose keeps the pattern right
  // for one-sided lists too.
  std::vector<int> fam_start(static_cast<std::size_t>(n_) + 1, 0), fams;
  for (int p = 0; p < n_; ++p) for_each_member(B, p, [&](int q) { ++fam_start[q + 1]; });
  for (int q = 0; q < n_; ++q) fam_start[q + 1] += fam_start[q];
  fams.resize(static_cast<std::size_t>(fam_start[n_]));
  {
    std::vector<int> fill(fam_start.begin(), fam_start.end() - 1);
    for (int p = 0; p < n_; ++p) for_each_member(B, p, [&](int q) { fams[fill[q]++] = p; });
  }
  // Column b holds every member of every family containing b (family coupling), or
  // (pairwise) all of b's own family and the center of each other family holding b.
  col_start_.assign(static_cast<std::size_t>(n_) + 1, 0);
  std::vector<int> mark(static_cast<std::size_t>(n_), -1), col;
  for (int b = 0; b < n_; ++b) {
    col.clear();
    auto add = [&](int q) {
      if (mark[q] != b) mark[q] = b, col.push_back(q);
    };
    for (int i = fam_start[b]; i < fam_start[b + 1]; ++i) {
      const int p = fams[i];
      if (coupling == Coupling::family || p == b)
        for_each_member(B, p, add);
      else
        add(p), add(b);
    }
    std::sort(col.begin(), col.end());
    rows_.insert(rows_.end(), col.begin(), col.end());
    col_start_[b + 1] = static_cast<int>(rows_.size());
  }
  if (nonzeros() >= std::numeric_limits<int>::max())
    throw std::runtime_error("sparsity: " + std::to_string(nonzeros()) +
                             " nonzeros exceed 32-bit indices; use the matrix-free solver");
  slot_start_.assign(static_cast<std::size_t>(n_) + 1, 0);
  for (int p = 0; p < n_; ++p) {
    slot_start_[p + 1] = slot_start_[p] + slot_count(coupling, B.family_size(p));
  }
  slots_.resize(static_cast<std::size_t>(slot_start_[n_]));
#pragma omp parallel for schedule(dynamic, 64)
  for (int p = 0; p < n_; ++p) {
    const int L = B.family_size(p), b0 = B.offsets[p];
    int* s = slots_.data() + slot_start_[p];
    auto member = [&](int a) { return a == 0 ? p : B.neighbor[b0 + a - 1]; };
    if (coupling == Coupling::family) {
      for (int b = 0; b <= L; ++b)
        for (int a = 0; a <= L; ++a) s[b * (L + 1) + a] = block_base(member(a), member(b));
    } else {
      for (int a = 0; a <= L; ++a) s[a] = block_base(member(a), p);
      for (int k = 1; k <= L; ++k) {
        s[L + 2 * k - 1] = block_base(p, member(k));
        s[L + 2 * k] = block_base(member(k), member(k));
      }
    }
  }
}

int SparsityPattern::block_base(int a, int b) const {
  const auto first = rows_.begin() + col_start_[b], last = rows_.begin() + col_start_[b + 1];
  const auto it = std::lower_bound(first, last, a);
  if (it == last || *it != a)
    throw std::out_of_range("sparsity: particles " + std::to_string(a) + " and " + std::to_string(b) +
                            " share no family");
  // Particle column b starts at col_start_[b] * dim^2 (each earlier particle column holds
  // dim columns of (its length * dim) entries).
  return col_start_[b] * dim_ * dim_ + static_cast<int>(it - first) * dim_;
}

SparseMatrix SparsityPattern::matrix() const {
  const int N = n_ * dim_;
  SparseMatrix K(N, N);
  K.resizeNonZeros(static_cast<Eigen::Index>(nonzeros()));
  int* outer = K.outerIndexPtr();
  int* inner = K.innerIndexPtr();
  int pos = 0;
  for (int b = 0; b < n_; ++b)
    for (int q = 0; q < dim_; ++q) {
      outer[b * dim_ + q] = pos;
      for (int e = col_start_[b]; e < col_start_[b + 1]; ++e)
        for (int r = 0; r < dim_; ++r) inner[pos++] = rows_[e] * dim_ + r;
    }
  outer[N] = pos;
  std::fill(K.valuePtr(), K.valuePtr() + pos, 0.0);
  return K;
}

}  // namespace pd
