// Sparse linear solvers behind one interface, and the rule that picks one.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "assembly/sparsity_pattern.hpp"

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
  std::string method = "auto";  // auto | cholmod | umfpack | cg | bicgstab
  std::string preconditioner = "auto";  // cg: ic | diagonal (auto: ic); bicgstab: ilut
  double tolerance = 1e-10;     // Krylov relative residual
  int max_iterations = 0;       // Krylov; 0: Eigen's default (2 n)
  // Direct factorisation up to this many nonzeros of the (reduced) matrix. CHOLMOD on
  // the delta/h = 3.5 tangent took 74 s and 2.4 GB at 200^2 particles (about 2.5e7
  // nonzeros) and did not finish at 400^2 (issue 7), while delta/h = 1.5 at 200^2
  // (about 4.6e6) factors in seconds; 8e6 keeps direct solves to a few seconds.
  std::int64_t direct_max_nonzeros = 8'000'000;
};

struct SolverChoice {
  std::string method;  // the concrete method
  std::string reason;  // one line for the run log
};

// The automatic rule (method == "auto"): a direct solver while the matrix has at most
// direct_max_nonzeros nonzeros -- CHOLMOD when symmetric (the caller asserts
// positive definiteness; a failure falls back to UMFPACK), UMFPACK otherwise -- and a
// preconditioned Krylov method above -- CG with incomplete Cholesky when symmetric,
// BiCGSTAB with ILUT otherwise. A named method is taken as given.
SolverChoice choose_linear_solver(const LinearSolverOptions& options, std::int64_t unknowns, std::int64_t nonzeros,
                                  bool symmetric);

// One concrete solver by name (cholmod, umfpack, cg, bicgstab). Throws on an unknown name.
std::unique_ptr<SparseSolver> make_sparse_solver(const std::string& method, const LinearSolverOptions& options);

// The solver a caller should use: chooses on the first factor(), and when a
// factorisation fails falls back -- CHOLMOD to UMFPACK, CG's incomplete Cholesky to
// a diagonal preconditioner -- telling `log` why. Throws when no fallback is left.
class AutoLinearSolver final : public SparseSolver {
 public:
  AutoLinearSolver(LinearSolverOptions options, bool symmetric, std::function<void(const std::string&)> log = {});
  std::string name() const override { return solver_ ? solver_->name() : "unset"; }
  void analyse(const SparseMatrix& A) override;
  bool factor(const SparseMatrix& A) override;  // throws instead of returning false
  LinearSolveStats solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override;
  const SolverChoice& choice() const { return choice_; }

 private:
  LinearSolverOptions options_;
  bool symmetric_;
  std::function<void(const std::string&)> log_;
  SolverChoice choice_;
  std::unique_ptr<SparseSolver> solver_;
};

}  // namespace pd
