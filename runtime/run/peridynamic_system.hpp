// The peridynamic body as a NonlinearSystem: the law's internal forces from the
// assembler plus the forces of the effects the scene calls for.
#pragma once

#include <vector>

#include "assembly/force_operator.hpp"
#include "effects/loads.hpp"
#include "solve/newton.hpp"

namespace pd {

// r(u) = f_internal(u) + sum of effect forces at the load factor; K = -dr/du. Symmetric
// when the law has an energy (its tangent is a Hessian) and every effect is; otherwise
// the linear solver must be a general one. The effects are borrowed, not owned.
class PeridynamicSystem final : public NonlinearSystem {
 public:
  // approximation (optional): the same law on a shorter horizon, whose stiffness
  // preconditions the matrix-free path (NonlinearSystem::approximate_tangent).
  PeridynamicSystem(const ForceOperator& assembler, std::vector<const Effect*> effects,
                    const ForceOperator* approximation = nullptr)
      : a_(assembler), effects_(std::move(effects)), approximation_(approximation) {}
  int size() const override { return a_.dofs(); }
  void residual(const Eigen::VectorXd& u, double load, Eigen::VectorXd& r) override {
    r.resize(size());
    a_.internal_forces(u.data(), r.data());
    for (const Effect* e : effects_) e->add_forces(u.data(), load, r.data());
  }
  void tangent(const Eigen::VectorXd& u, double load, SparseMatrix& K, Eigen::VectorXd* r) override {
    if (r) r->resize(size());
    a_.stiffness(u.data(), K, r ? r->data() : nullptr);
    for (const Effect* e : effects_) {
      if (r) e->add_forces(u.data(), load, r->data());
      e->add_stiffness(u.data(), load, a_.pattern(), K);
    }
  }
  bool symmetric() const override {
    bool s = a_.has_energy();  // false under collocation (domain.quadrature: obq)
    for (const Effect* e : effects_) s = s && e->symmetric();
    return s;
  }
  bool has_jvp() const override { return a_.variant().jvp != nullptr; }
  void jvp(const Eigen::VectorXd& u, double load, const Eigen::VectorXd& v, Eigen::VectorXd& Kv) override {
    Kv.resize(size());
    a_.stiffness_product(u.data(), v.data(), Kv.data());
    for (const Effect* e : effects_) e->add_stiffness_product(u.data(), load, v.data(), Kv.data());
  }
  void diagonal(const Eigen::VectorXd& u, double load, Eigen::VectorXd& d) override {
    d.resize(size());
    a_.stiffness_diagonal(u.data(), d.data());
    for (const Effect* e : effects_) e->add_stiffness_diagonal(u.data(), load, d.data());
  }
  bool has_approximate_tangent() const override { return approximation_ != nullptr; }
  void approximate_tangent(const Eigen::VectorXd& u, double load, SparseMatrix& P) override {
    approximation_->stiffness(u.data(), P);
    for (const Effect* e : effects_) e->add_stiffness(u.data(), load, approximation_->pattern(), P);
  }
  // Y = xi + (u_q - u_p) is rounded against |xi| (family_gather.cpp): the longest bond.
  double rounding_length() const override { return a_.longest_bond(); }

 private:
  const ForceOperator& a_;
  std::vector<const Effect*> effects_;
  const ForceOperator* approximation_;
};

}  // namespace pd
