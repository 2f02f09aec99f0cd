// The peridynamic body as a NonlinearSystem: internal forces from the assembler plus external loads.
#pragma once

#include "assembly/assembler.hpp"
#include "solve/newton.hpp"

namespace pd {

// r(u) = f_internal(u) + load * f_external, K = -dr/du = the assembler's stiffness.
// Symmetric when the law has an energy (its tangent is a Hessian); otherwise the
// linear solver must be a general one.
class PeridynamicSystem final : public NonlinearSystem {
 public:
  PeridynamicSystem(const FamilyAssembler& assembler, Eigen::VectorXd external_forces)
      : a_(assembler), external_(std::move(external_forces)) {}
  int size() const override { return a_.dofs(); }
  void residual(const Eigen::VectorXd& u, double load, Eigen::VectorXd& r) override {
    r.resize(size());
    a_.internal_forces(u.data(), r.data());
    if (external_.size()) r += load * external_;
  }
  void tangent(const Eigen::VectorXd& u, double load, SparseMatrix& K, Eigen::VectorXd* r) override {
    if (r) r->resize(size());
    a_.stiffness(u.data(), K, r ? r->data() : nullptr);
    if (r && external_.size()) *r += load * external_;
  }
  bool symmetric() const override { return a_.variant().energy != nullptr; }
  bool has_jvp() const override { return a_.variant().jvp != nullptr; }
  void jvp(const Eigen::VectorXd& u, double, const Eigen::VectorXd& v, Eigen::VectorXd& Kv) override {
    Kv.resize(size());
    a_.stiffness_product(u.data(), v.data(), Kv.data());
  }
  void diagonal(const Eigen::VectorXd& u, double, Eigen::VectorXd& d) override {
    d.resize(size());
    a_.stiffness_diagonal(u.data(), d.data());
  }

 private:
  const FamilyAssembler& a_;
  Eigen::VectorXd external_;
};

}  // namespace pd
