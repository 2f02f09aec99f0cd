// Hand-written PCG and right-preconditioned GMRES(m) (Saad, Iterative Methods, alg. 9.1 and 9.5).
// Eigen's iterative solvers take a matrix-free operator only through a MatrixReplacement
// with traits and product specialisations; a plain loop over a std::function is shorter
// and lets the product be the assembler's, which is parallel already.
#include "solve/matrix_free_krylov.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "interrupt.hpp"
#include "solve/progress.hpp"

namespace pd {

Eigen::VectorXd safe_inverse_diagonal(const Eigen::VectorXd& d) {
  Eigen::VectorXd inv(d.size());
  const double scale = d.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < d.size(); ++i)
    inv[i] = (std::isfinite(d[i]) && std::abs(d[i]) > 1e-14 * scale) ? 1.0 / d[i]
                                                                     : 1.0 / (scale > 0 ? scale : 1.0);
  return inv;
}

LinearOperator diagonal_preconditioner(Eigen::VectorXd inv_diagonal) {
  return
      [d = std::move(inv_diagonal)](const Eigen::VectorXd& r, Eigen::VectorXd& z) { z = d.cwiseProduct(r); };
}

KrylovResult preconditioned_cg(const LinearOperator& A, const LinearOperator& M, const Eigen::VectorXd& b,
                               Eigen::VectorXd& x, double tol, int max_it) {
  KrylovResult res;
  const double bnorm = b.norm();
  if (bnorm == 0) {
    x.setZero();
    res.converged = true;
    return res;
  }
  if (x.size() != b.size()) x = Eigen::VectorXd::Zero(b.size());
  Eigen::VectorXd r(b.size()), Ap(b.size());
  A(x, Ap);
  r = b - Ap;
  Eigen::VectorXd z(b.size());
  M(r, z);
  Eigen::VectorXd p = z;
  double rz = r.dot(z);
  const ProgressPhase phase("matrix-free CG of " + std::to_string(b.size()) + " unknowns");
  for (res.iterations = 0; res.iterations < max_it; ++res.iterations) {
    const double rnorm = r.norm();
    progress_iteration(res.iterations, rnorm / bnorm);
    if (rnorm <= tol * bnorm) break;
    throw_if_interrupted("during a matrix-free CG solve");
    A(p, Ap);
    const double pAp = p.dot(Ap);
    if (!(pAp > 0)) {  // not positive definite along p: stop, report the residual
      res.indefinite = true;
      break;
    }
    const double alpha = rz / pAp;
    x += alpha * p;
    r -= alpha * Ap;
    M(r, z);
    const double rz_new = r.dot(z);
    p = z + (rz_new / rz) * p;
    rz = rz_new;
  }
  A(x, Ap);
  res.relative_residual = (b - Ap).norm() / bnorm;
  // The recurrence residual drifts from the true one; allow a little slack.
  res.converged = res.relative_residual <= 10 * tol;
  return res;
}

KrylovResult preconditioned_gmres(const LinearOperator& A, const LinearOperator& M, const Eigen::VectorXd& b,
                                  Eigen::VectorXd& x, double tol, int restart, int max_it) {
  KrylovResult res;
  const Eigen::Index n = b.size();
  const double bnorm = b.norm();
  if (bnorm == 0) {
    x.setZero();
    res.converged = true;
    return res;
  }
  if (x.size() != n) x = Eigen::VectorXd::Zero(n);
  const int m = std::max(1, restart);
  Eigen::MatrixXd V(n, m + 1), H = Eigen::MatrixXd::Zero(m + 1, m);
  Eigen::VectorXd cs(m), sn(m), g(m + 1), w(n), Ax(n), z(n);
  const ProgressPhase phase("matrix-free GMRES of " + std::to_string(n) + " unknowns");
  while (res.iterations < max_it) {
    A(x, Ax);
    Eigen::VectorXd r = b - Ax;
    double beta = r.norm();
    res.relative_residual = beta / bnorm;
    if (res.relative_residual <= tol) break;
    V.col(0) = r / beta;
    g.setZero();
    g[0] = beta;
    int j = 0;
    for (; j < m && res.iterations < max_it; ++j, ++res.iterations) {
      throw_if_interrupted("during a matrix-free GMRES solve");
      M(V.col(j), z);
      A(z, w);                        // right preconditioning: A M v
      for (int i = 0; i <= j; ++i) {  // modified Gram-Schmidt
        H(i, j) = w.dot(V.col(i));
        w -= H(i, j) * V.col(i);
      }
      H(j + 1, j) = w.norm();
      if (H(j + 1, j) > 0) V.col(j + 1) = w / H(j + 1, j);
      for (int i = 0; i < j; ++i) {  // apply the previous rotations to the new column
        const double t = cs[i] * H(i, j) + sn[i] * H(i + 1, j);
        H(i + 1, j) = -sn[i] * H(i, j) + cs[i] * H(i + 1, j);
        H(i, j) = t;
      }
      const double den = std::hypot(H(j, j), H(j + 1, j));
      cs[j] = den > 0 ? H(j, j) / den : 1.0;
      sn[j] = den > 0 ? H(j + 1, j) / den : 0.0;
      H(j, j) = den;
      H(j + 1, j) = 0;
      g[j + 1] = -sn[j] * g[j];
      g[j] = cs[j] * g[j];
      progress_iteration(res.iterations + 1, std::abs(g[j + 1]) / bnorm);
      if (std::abs(g[j + 1]) <= tol * bnorm || den == 0) {
        ++j, ++res.iterations;
        break;
      }
    }
    // x += M^-1 V_j y with H_j y = g_j (upper triangular).
    const Eigen::VectorXd y = H.topLeftCorner(j, j).triangularView<Eigen::Upper>().solve(g.head(j));
    M(V.leftCols(j) * y, z);
    x += z;
    if (H.topLeftCorner(j, j).diagonal().cwiseAbs().minCoeff() == 0)
      break;  // breakdown: nothing more to gain
  }
  A(x, Ax);
  res.relative_residual = (b - Ax).norm() / bnorm;
  res.converged = res.relative_residual <= 10 * tol;
  return res;
}

}  // namespace pd
