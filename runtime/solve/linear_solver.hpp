// Sparse linear solvers behind one interface (the rule that picks one: solve/solver_plan.hpp).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "assembly/sparsity_pattern.hpp"
#include "input/solver_spec.hpp"
#include "solve/solver_plan.hpp"

namespace pd {

struct LinearSolveStats {
  std::string method;
  int iterations = 0;            // Krylov iterations (0 for a direct solve)
  double estimated_error = 0.0;  // Krylov: |b - A x| / |b| as the method estimates it
  bool converged = true;
};

// analyse() once per pattern (orderings, symbolic factorisation), factor() per matrix
// (numeric factorisation, or the preconditioner), then any number of solve()s.
class SparseSolver {
 public:
  virtual ~SparseSolver() = default;
  virtual std::string name() const = 0;
  virtual void analyse(const SparseMatrix& A) = 0;
  // False when the factorisation fails (CHOLMOD: not positive definite; UMFPACK:
  // singular; incomplete Cholesky: breakdown); failure() then says why.
  virtual bool factor(const SparseMatrix& A) = 0;
  virtual LinearSolveStats solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) = 0;
  const std::string& failure() const { return failure_; }

 protected:
  std::string failure_;
};

struct LinearSolverOptions {
  LinearMethod method = LinearMethod::automatic;  // automatic | cholmod | umfpack | cg | bicgstab
  Preconditioner preconditioner =
      Preconditioner::automatic;  // cg: ic | diagonal (automatic: ic); bicgstab: ilut
  double tolerance = 1e-10;       // Krylov relative residual
  int max_iterations = 0;         // Krylov; 0: Eigen's default (2 n)
  // automatic: a direct factorisation up to this many nonzeros of the (reduced) matrix
  // (choose_linear_solver in solve/solver_plan.hpp); the scene's default.
  std::int64_t direct_max_nonzeros = SolverSpec{}.direct_max_nonzeros;
};

// One concrete solver (cholmod, umfpack, cg, bicgstab with o.preconditioner). Throws
// std::invalid_argument on a method/preconditioner pair that does not exist.
std::unique_ptr<SparseSolver> make_sparse_solver(LinearMethod method, const LinearSolverOptions& options);

// The solver a caller should use: chooses on the first factor() (choose_linear_solver),
// and when a factorisation fails falls back (fallback_after_failure), telling `log`
// why. Throws when no fallback is left.
class AutoLinearSolver final : public SparseSolver {
 public:
  AutoLinearSolver(LinearSolverOptions options, bool symmetric,
                   std::function<void(const std::string&)> log = {});
  std::string name() const override { return solver_ ? solver_->name() : "unset"; }
  void analyse(const SparseMatrix& A) override;
  bool factor(const SparseMatrix& A) override;  // throws instead of returning false
  LinearSolveStats solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override;
  const SolverChoice& choice() const { return choice_; }  // after the first analyse()/factor()

 private:
  LinearSolverOptions options_;
  bool symmetric_;
  std::function<void(const std::string&)> log_;
  bool chosen_ = false;
  SolverChoice choice_;
  std::unique_ptr<SparseSolver> solver_;
};

}  // namespace pd
