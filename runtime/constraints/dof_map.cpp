// DofMap numbering and the K_ff / K_fc extraction plans.
#include "constraints/dof_map.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

namespace pd {

DofMap::DofMap(std::span<const char> constrained, std::span<const double> prescribed) {
  if (prescribed.size() != constrained.size())
    throw std::invalid_argument("DofMap: flags and values differ in size");
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

void DofMap::tie(std::vector<TiedDof> ties) {
  const int n = size();
  std::vector<char> tied(static_cast<std::size_t>(n), 0);
  for (const TiedDof& t : ties_) tied[t.dof] = 1;
  for (const TiedDof& t : ties) {
    if (t.dof < 0 || t.dof >= n)
      throw std::out_of_range("DofMap::tie: dof " + std::to_string(t.dof) + " out of range");
    if (tied[t.dof]) throw std::invalid_argument("DofMap::tie: dof " + std::to_string(t.dof) + " tied twice");
    if (free_index_[t.dof] < 0)
      throw std::invalid_argument("DofMap::tie: dof " + std::to_string(t.dof) +
                                  " is constrained; it cannot also be tied");
    if (t.masters.size() != t.coefficients.size())
      throw std::invalid_argument("DofMap::tie: dof " + std::to_string(t.dof) +
                                  ": masters and coefficients differ in size");
    tied[t.dof] = 1;
  }
  for (const TiedDof& t : ties)
    for (int m : t.masters) {
      if (m < 0 || m >= n)
        throw std::out_of_range("DofMap::tie: master " + std::to_string(m) + " out of range");
      if (tied[m])
        throw std::invalid_argument("DofMap::tie: dof " + std::to_string(t.dof) + " is tied to dof " +
                                    std::to_string(m) + ", which is itself tied");
    }
  for (TiedDof& t : ties) ties_.push_back(std::move(t));
  std::sort(ties_.begin(), ties_.end(), [](const TiedDof& a, const TiedDof& b) { return a.dof < b.dof; });
  free_.clear();
  for (int i = 0; i < n; ++i) {
    if (free_index_[i] < 0) continue;  // constrained
    if (tied[i]) {
      free_index_[i] = -1;
      continue;
    }
    free_index_[i] = static_cast<int>(free_.size());
    free_.push_back(i);
  }
}

Eigen::VectorXd DofMap::restrict_free(const Eigen::VectorXd& full) const {
  Eigen::VectorXd r(free_count());
  for (int i = 0; i < free_count(); ++i) r[i] = full[free_[i]];
  return r;
}

void DofMap::expand_free(const Eigen::VectorXd& reduced, Eigen::VectorXd& full) const {
  for (int i = 0; i < free_count(); ++i) full[free_[i]] = reduced[i];
  for (const TiedDof& t : ties_) {
    double v = 0;
    for (std::size_t k = 0; k < t.masters.size(); ++k) v += t.coefficients[k] * full[t.masters[k]];
    full[t.dof] = v;
  }
}

void DofMap::apply_ties(double* full, double factor) const {
  for (const TiedDof& t : ties_) {
    double v = factor * t.offset;
    for (std::size_t k = 0; k < t.masters.size(); ++k) v += t.coefficients[k] * full[t.masters[k]];
    full[t.dof] = v;
  }
}

void DofMap::apply_prescribed(Eigen::VectorXd& full, double factor) const {
  for (int i = 0; i < constrained_count(); ++i)
    full[constrained_[i]] = path_ ? path_(factor, i) : factor * prescribed_[i];
  apply_ties(full.data(), factor);
}

ReducedSystem::ReducedSystem(const DofMap& dofs, const SparseMatrix& K) : dofs_(&dofs) {
  if (K.rows() != dofs.size() || K.cols() != dofs.size())
    throw std::invalid_argument("ReducedSystem: size mismatch");
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
  if (dofs.tied_count() == 0) {
    build(Kff_, ff_source_, false);
    build(Kfc_, fc_source_, true);
    return;
  }
  // S K P: the output column of dof j gathers K's column j and, weighted, the columns of
  // the dofs tied to j; rows are the free dofs'.
  weighted_ = true;
  std::vector<std::vector<std::pair<int, double>>> dependents(static_cast<std::size_t>(dofs.size()));
  for (const TiedDof& t : dofs.ties())
    for (std::size_t k = 0; k < t.masters.size(); ++k)
      dependents[t.masters[k]].emplace_back(t.dof, t.coefficients[k]);
  auto build_weighted = [&](SparseMatrix& out, WeightedPlan& plan, bool constrained_cols) {
    const int ncols = constrained_cols ? dofs.constrained_count() : dofs.free_count();
    out.resize(dofs.free_count(), ncols);
    std::vector<int> outer(static_cast<std::size_t>(ncols) + 1, 0), inner;
    plan = WeightedPlan{};
    plan.start.push_back(0);
    std::map<int, std::vector<std::pair<int, double>>> rows;  // free row -> (value position, coefficient)
    for (int c = 0; c < ncols; ++c) {
      const int j = constrained_cols ? dofs.constrained_dofs()[c] : dofs.free_dofs()[c];
      rows.clear();
      auto add_column = [&](int col, double coefficient) {
        for (int k = K.outerIndexPtr()[col]; k < K.outerIndexPtr()[col + 1]; ++k) {
          const int fi = dofs.free_index(K.innerIndexPtr()[k]);
          if (fi >= 0) rows[fi].emplace_back(k, coefficient);
        }
      };
      add_column(j, 1.0);
      for (const auto& [s, coefficient] : dependents[j]) add_column(s, coefficient);
      for (const auto& [fi, terms] : rows) {
        inner.push_back(fi);
        for (const auto& [k, coefficient] : terms) {
          plan.source.push_back(k);
          plan.coefficient.push_back(coefficient);
        }
        plan.start.push_back(static_cast<int>(plan.source.size()));
      }
      outer[c + 1] = static_cast<int>(inner.size());
    }
    out.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
    std::copy(outer.begin(), outer.end(), out.outerIndexPtr());
    std::copy(inner.begin(), inner.end(), out.innerIndexPtr());
    std::fill(out.valuePtr(), out.valuePtr() + inner.size(), 0.0);
  };
  build_weighted(Kff_, ff_plan_, false);
  build_weighted(Kfc_, fc_plan_, true);
}

void ReducedSystem::update(const SparseMatrix& K) {
  const double* v = K.valuePtr();
  if (weighted_) {
    auto gather = [v](const WeightedPlan& plan, SparseMatrix& out) {
      double* o = out.valuePtr();
      for (std::size_t e = 0; e + 1 < plan.start.size(); ++e) {
        double sum = 0;
        for (int t = plan.start[e]; t < plan.start[e + 1]; ++t)
          sum += plan.coefficient[t] * v[plan.source[t]];
        o[e] = sum;
      }
    };
    gather(ff_plan_, Kff_);
    gather(fc_plan_, Kfc_);
    return;
  }
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
