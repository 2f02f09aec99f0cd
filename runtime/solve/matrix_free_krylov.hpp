// Krylov methods on an operator given only as a product: preconditioned CG and GMRES.
#pragma once

#include <Eigen/Core>
#include <functional>

namespace pd {

// y = A x. The matrix-free Newton-Krylov path wraps the kernels' tangent-vector
// product in one of these.
using LinearOperator = std::function<void(const Eigen::VectorXd& x, Eigen::VectorXd& y)>;

struct KrylovResult {
  int iterations = 0;
  double relative_residual = 0;  // |b - A x| / |b| at exit (recomputed, not the recurrence's)
  bool converged = false;
  bool indefinite = false;  // CG met p^T A p <= 0: A (or M) is not positive definite
};

// Conjugate gradients for symmetric positive definite A, preconditioned by M ~ A^-1
// (z = M r; symmetric positive definite). x is the initial guess and the result.
// Stops at |b - A x| <= tolerance |b|.
KrylovResult preconditioned_cg(const LinearOperator& A, const LinearOperator& M, const Eigen::VectorXd& b,
                               Eigen::VectorXd& x, double tolerance, int max_iterations);

// Restarted GMRES(m) for a general A, right-preconditioned by M ~ A^-1 so the
// residual it minimises is the true one.
KrylovResult preconditioned_gmres(const LinearOperator& A, const LinearOperator& M, const Eigen::VectorXd& b,
                                  Eigen::VectorXd& x, double tolerance, int restart, int max_iterations);

// The Jacobi preconditioner z = inv_diagonal .* r as an operator.
LinearOperator diagonal_preconditioner(Eigen::VectorXd inv_diagonal);

// 1/d where d is usable, 1 where it is zero or not finite (a dof no bond reaches):
// a Jacobi preconditioner that never divides by zero.
Eigen::VectorXd safe_inverse_diagonal(const Eigen::VectorXd& diagonal);

}  // namespace pd
