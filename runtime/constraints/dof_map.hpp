// Dirichlet conditions by elimination: free/constrained dof numbering and the reduced system.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <span>
#include <vector>

#include "assembly/sparsity_pattern.hpp"
#include "constraints/prescribed_motion.hpp"
#include "discretize/tied_dof.hpp"

namespace pd {

// Numbers the free dofs 0..nf-1 in ascending global order and keeps the prescribed
// value of every constrained dof (at full load; a load factor s scales them).
//
// Tied dofs (multipoint constraints, tie()) are eliminated by collocation: with
// u = P u_f + g (P: identity on the free dofs, the coefficients on the tied ones), the
// reduced equations are the free rows of the residual, r_f(P u_f + g) = 0, and the reduced
// tangent is S K P (S selects the free rows). The tied dofs' own residual rows are not
// equations: a fictitious particle carries no equation of motion, it only lends its
// displacement to its neighbours' families. The symmetric reduction P^T K P would add
// those rows to the masters' and break the patch test (tests/solve/test_fictitious_layer:
// the layer's outer particles have cut families, so their rows are not zero under a
// homogeneous strain); S K P is not symmetric, so a tied map reports keeps_symmetry() false.
class DofMap {
 public:
  DofMap() = default;
  // constrained[i] != 0 marks dof i; prescribed[i] is its value (ignored when free).
  DofMap(std::span<const char> constrained, std::span<const double> prescribed);
  // From a list of constrained dofs (any order, no repeats) and their values.
  static DofMap from_list(int n_dofs, std::span<const int> dofs, std::span<const double> values);

  int size() const { return static_cast<int>(free_index_.size()); }
  int free_count() const { return static_cast<int>(free_.size()); }
  int constrained_count() const { return static_cast<int>(constrained_.size()); }
  // Reduced index of a dof, -1 when constrained.
  int free_index(int dof) const { return free_index_[dof]; }
  const std::vector<int>& free_dofs() const { return free_; }
  const std::vector<int>& constrained_dofs() const { return constrained_; }
  // Prescribed values, one per constrained dof (constrained_dofs() order).
  const std::vector<double>& prescribed() const { return prescribed_; }

  // Ties the given dofs (each free until now, at most one tie each) to their masters.
  // Throws std::invalid_argument on a constrained or repeated tied dof, or a master that
  // is itself tied.
  void tie(std::vector<TiedDof> ties);
  int tied_count() const { return static_cast<int>(ties_.size()); }
  const std::vector<TiedDof>& ties() const { return ties_; }
  // S K P is symmetric when K is only without ties.
  bool keeps_symmetry() const { return ties_.empty(); }

  Eigen::VectorXd restrict_free(const Eigen::VectorXd& full) const;
  // full[free] = reduced, then full[tied] = the ties' linear part over `full` (no offset):
  // for an increment (zero on the constrained dofs) this is P reduced. Constrained
  // entries are untouched.
  void expand_free(const Eigen::VectorXd& reduced, Eigen::VectorXd& full) const;
  // full[constrained] = factor * prescribed, or the load path's values at `factor`; then
  // the ties (apply_ties).
  void apply_prescribed(Eigen::VectorXd& full, double factor = 1.0) const;
  // full[tied] = sum coefficient * full[master] + factor * offset, from the current free
  // and constrained values (the dynamic drivers call it after each step's update).
  void apply_ties(double* full, double factor = 1.0) const;
  // A prescribed motion that is not proportional to the load (a rotation: scaling its
  // displacement by 1/2 is a rotation by 30 degrees *and* a 13% contraction, not a
  // rotation by 45) gives its values at a load factor: path(load, i) for the i-th
  // constrained dof; it must give prescribed()[i] at load 1.
  using LoadPath = std::function<double(double load, int i)>;
  void set_load_path(LoadPath path) { path_ = std::move(path); }
  // A dynamic run's prescribed motion: each constrained dof's function of time
  // (constraints/prescribed_motion.hpp). apply_motion sets u and v (v: when not empty) of the
  // constrained dofs at time t, then the tied dofs' from their masters (v: the ties'
  // linear part).
  void set_motion(PrescribedMotion motion) { motion_ = std::move(motion); }
  const PrescribedMotion& motion() const { return motion_; }
  void apply_motion(double t, std::vector<double>& u, std::vector<double>& v) const;

 private:
  std::vector<int> free_index_, free_, constrained_;
  std::vector<double> prescribed_;
  LoadPath path_;
  PrescribedMotion motion_;
  std::vector<TiedDof> ties_;
};

// K_ff and K_fc of a matrix with a fixed pattern. The index plans are built once; each
// update() is then a gather of values. K_ff keeps K's symmetry (same rows and columns
// removed), so CHOLMOD applies whenever it applied to K. With tied dofs the blocks are
// S K P (free rows; a free or constrained column plus coefficient x the columns of the
// dofs tied to it) and update() sums the weighted sources of each entry.
class ReducedSystem {
 public:
  ReducedSystem(const DofMap& dofs, const SparseMatrix& pattern);
  // Copies the values of K (same pattern as at construction) into K_ff and K_fc.
  void update(const SparseMatrix& K);
  const SparseMatrix& Kff() const { return Kff_; }
  const SparseMatrix& Kfc() const { return Kfc_; }
  // Right-hand side b_f - K_fc u_c for the full vector b and the constrained values
  // u_c (constrained_dofs() order; empty = zero, as for a Newton increment). The ties'
  // offsets are not in it (Newton carries them in u through apply_prescribed).
  Eigen::VectorXd rhs(const Eigen::VectorXd& b_full, const Eigen::VectorXd& u_c) const;

 private:
  const DofMap* dofs_;
  SparseMatrix Kff_, Kfc_;
  std::vector<int> ff_source_, fc_source_;  // value-array positions in K
  // With ties: entry e of a block sums coefficient[t] * K.value[source[t]] over
  // t in [start[e], start[e + 1]).
  struct WeightedPlan {
    std::vector<int> start, source;
    std::vector<double> coefficient;
  };
  WeightedPlan ff_plan_, fc_plan_;
  bool weighted_ = false;
};

}  // namespace pd
