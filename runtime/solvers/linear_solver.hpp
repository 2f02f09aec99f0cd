// Sparse linear solvers behind one interface: CHOLMOD (symmetric positive definite),
// UMFPACK (general), and preconditioned Krylov methods (CG with incomplete Cholesky
// for symmetric systems, BiCGSTAB with ILUT otherwise) for systems too large to factor.
#pragma once

#include <memory>
#include <string>

#include "assemble/sparsity.hpp"

namespace pd {

struct LinearSolveReport {
  std::string method;
  int iterations = 0;      // Krylov iterations (0 for direct solvers)
  double error = 0;        // Krylov estimated relative residual
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  // Factors (direct) or builds the preconditioner (Krylov) for A. Throws on failure.
  virtual void factor(const SparseMatrix& A) = 0;
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b, LinearSolveReport& report) = 0;
  virtual std::string name() const = 0;
};

// name: cholmod, umfpack, cg, bicgstab, or auto (chosen from size and symmetry:
// direct below `direct_limit` unknowns, CHOLMOD when symmetric, else UMFPACK;
// CG or BiCGSTAB above). The reason for the choice is written to `why`.
std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name, long long unknowns, bool symmetric,
                                                 double krylov_tolerance, std::string& why,
                                                 long long direct_limit = 400000);

}  // namespace pd
