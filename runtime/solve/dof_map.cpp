// DofMap numbering and the K_ff / K_fc extraction plans.
#include "solve/dof_map.hpp"

#include <stdexcept>
#include <string>

namespace pd {

DofMap::DofMap(std::span<const char> constrained, std::span<const double> prescribed) {
  if (prescribed.size() != constrained.size()) throw std::invalid_argument("DofMap: flags and values differ in size");
  free_index_.assign(constrained.size(), -1);
  for (std::size_t i = 0; i < constrained.size(); ++i) {
    if (constrained[i]) {
      constrained_.push_back(static_cast<int>(i));
      prescribed_.push_back(prescribed[i]);
    } else {
      free_index_[i] = static_cast<int>(free_.size());
      free_.push_back(static_cast<int>(i));
    }
  }
}

DofMap DofMap::from_list(int n_dofs, std::span<const int> dofs, std::span<const double> values) {
  if (dofs.size() != values.size()) throw std::invalid_argument("DofMap: dofs and values differ in size");
  std::vector<char> flag(static_cast<std::size_t>(n_dofs), 0);
  std::vector<double> value(static_cast<std::size_t>(n_dofs), 0.0);
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    const int d = dofs[i];
    if (d < 0 || d >= n_dofs) throw std::out_of_range("DofMap: dof " + std::to_string(d) + " out of range");
    if (flag[d]) throw std::invalid_argument("DofMap: dof " + std::to_string(d) + " constrained twice");
    flag[d] = 1;
    value[d] = values[i];
  }
  return DofMap(flag, value);
}

Eigen::VectorXd DofMap::restrict_free(const Eigen::VectorXd& full) const {
  Eigen::VectorXd r(free_count());
  for (int i = 0; i < free_count(); ++i) r[i] = full[free_[i]];
  return r;
}

void DofMap::expand_free(const Eigen::VectorXd& reduced, Eigen::VectorXd& full) const {
  for (int i = 0; i < free_count(); ++i) full[free_[i]] = reduced[i];
}

void DofMap::apply_prescribed(Eigen::VectorXd& full, double factor) const {
  for (int i = 0; i < constrained_count(); ++i) full[constrained_[i]] = path_ ? path_(factor, i) : factor * prescribed_[i];
}

ReducedSystem::ReducedSystem(const DofMap& dofs, const SparseMatrix& K) : dofs_(&dofs) {
  if (K.rows() != dofs.size() || K.cols() != dofs.size()) throw std::invalid_argument("ReducedSystem: size mismatch");
  std::vector<int> cindex(static_cast<std::size_t>(dofs.size()), -1);
  for (int i = 0; i < dofs.constrained_count(); ++i) cindex[dofs.constrained_dofs()[i]] = i;
  // Both blocks keep K's column-major order: column by column, rows ascending.
  auto build = [&](SparseMatrix& out, std::vector<int>& source, bool constrained_cols) {
    const int ncols = constrained_cols ? dofs.constrained_count() : dofs.free_count();
    out.resize(dofs.free_count(), ncols);
    std::vector<int> outer(static_cast<std::size_t>(ncols) + 1, 0), inner;
    for (int c = 0; c < ncols; ++c) {
      const int j = constrained_cols ? dofs.constrained_dofs()[c] : dofs.free_dofs()[c];
      for (int k = K.outerIndexPtr()[j]; k < K.outerIndexPtr()[j + 1]; ++k) {
        const int fi = dofs.free_index(K.innerIndexPtr()[k]);
        if (fi < 0) continue;
        inner.push_back(fi);
        source.push_back(k);
      }
      outer[c + 1] = static_cast<int>(inner.size());
    }
    out.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
    std::copy(outer.begin(), outer.end(), out.outerIndexPtr());
    std::copy(inner.begin(), inner.end(), out.innerIndexPtr());
    std::fill(out.valuePtr(), out.valuePtr() + inner.size(), 0.0);
  };
  if (!K.isCompressed()) throw std::invalid_argument("ReducedSystem: K must be compressed");
  build(Kff_, ff_source_, false);
  build(Kfc_, fc_source_, true);
}

void ReducedSystem::update(const SparseMatrix& K) {
  const double* v = K.valuePtr();
  double* ff = Kff_.valuePtr();
  for (std::size_t i = 0; i < ff_source_.size(); ++i) ff[i] = v[ff_source_[i]];
  double* fc = Kfc_.valuePtr();
  for (std::size_t i = 0; i < fc_source_.size(); ++i) fc[i] = v[fc_source_[i]];
}

Eigen::VectorXd ReducedSystem::rhs(const Eigen::VectorXd& b_full, const Eigen::VectorXd& u_c) const {
  Eigen::VectorXd b = dofs_->restrict_free(b_full);
  if (u_c.size() > 0) b -= Kfc_ * u_c;
  return b;
}

}  // namespace pd
