// MLS shape functions: moment matrix, its condition number, phi = B^T A^-1 p(x).
#include "discretize/mls.hpp"

#include <fmt/core.h>

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

namespace pd {

double mls_quartic_weight(double d) {
  if (d > 1.0) return 0.0;
  const double d2 = d * d;
  return 1.0 - 6.0 * d2 + 8.0 * d2 * d - 3.0 * d2 * d2;
}

int mls_basis_size(int dim) { return (dim + 1) * (dim + 2) / 2; }

namespace {
// p(s) = {1, s_x, s_y, [s_z], s_x s_y, [s_y s_z, s_z s_x], s_x^2, s_y^2, [s_z^2]} (eq. 3.21's order).
void quadratic_basis(const double* s, int dim, double* p) {
  int i = 0;
  p[i++] = 1.0;
  for (int a = 0; a < dim; ++a) p[i++] = s[a];
  for (int a = 0; a < dim; ++a) {
    const int b = (a + 1) % dim;
    if (dim == 2 && a == 1) break;  // 2D has the one product s_x s_y
    p[i++] = s[a] * s[b];
  }
  for (int a = 0; a < dim; ++a) p[i++] = s[a] * s[a];
}
}  // namespace

MlsShape mls_shape_functions(const double* x, int dim, std::span<const double> positions,
                             std::span<const int> candidates, double support, const std::string& what,
                             double max_condition) {
  const int m = mls_basis_size(dim);
  std::vector<int> inside;
  std::vector<double> weight, basis;  // basis: [n_inside * m]
  double s[3], p[10];
  for (int a : candidates) {
    double r2 = 0.0;
    for (int c = 0; c < dim; ++c) {
      s[c] = (positions[static_cast<std::size_t>(a) * dim + c] - x[c]) / support;
      r2 += s[c] * s[c];
    }
    const double W = mls_quartic_weight(std::sqrt(r2));
    if (W <= 0.0) continue;
    quadratic_basis(s, dim, p);
    inside.push_back(a);
    weight.push_back(W);
    basis.insert(basis.end(), p, p + m);
  }
  auto where = [&] {
    std::string at = fmt::format("({:.6g}", x[0]);
    for (int c = 1; c < dim; ++c) at += fmt::format(", {:.6g}", x[c]);
    return what + " at " + at + ")";
  };
  const int n = static_cast<int>(inside.size());
  if (n < m)
    throw std::runtime_error(
        fmt::format("MLS: {} has {} nodes within the support r_w = {:.6g}, fewer than the {} terms "
                    "of the quadratic basis (eq. 3.20); enlarge domain.gauss_points.support",
                    where(), n, support, m));
  // A = sum_a W_a p(x_a) p(x_a)^T (eq. 3.35).
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(m, m);
  for (int a = 0; a < n; ++a) {
    const Eigen::Map<const Eigen::VectorXd> pa(basis.data() + static_cast<std::ptrdiff_t>(a) * m, m);
    A.noalias() += weight[a] * pa * pa.transpose();
  }
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
  const Eigen::MatrixXd Ainv = lu.inverse();
  // kappa = ||A||_inf ||A^-1||_inf (eqs. 3.39-3.40); a singular A gives Inf or NaN here.
  const double kappa = A.cwiseAbs().rowwise().sum().maxCoeff() * Ainv.cwiseAbs().rowwise().sum().maxCoeff();
  if (!(kappa <= max_condition))
    throw std::runtime_error(
        fmt::format("MLS: {}: the moment matrix is ill-conditioned (row-sum condition number "
                    "{:.3g} > {:.3g}, eq. 3.39; {} nodes in the support r_w = {:.6g}); enlarge "
                    "domain.gauss_points.support",
                    where(), kappa, max_condition, n, support));
  // A v = p(x) (eq. 3.36); x is the origin of the scaled coordinates, so p(x) = e_0.
  Eigen::VectorXd px = Eigen::VectorXd::Zero(m);
  px[0] = 1.0;
  const Eigen::VectorXd v = lu.solve(px);
  MlsShape shape;
  shape.node = std::move(inside);
  shape.phi.resize(static_cast<std::size_t>(n));
  shape.condition = kappa;
  // phi_a = W_a p(x_a)^T v (eqs. 3.37-3.38).
  for (int a = 0; a < n; ++a) {
    double dot = 0.0;
    for (int j = 0; j < m; ++j) dot += basis[static_cast<std::size_t>(a) * m + j] * v[j];
    shape.phi[static_cast<std::size_t>(a)] = weight[a] * dot;
  }
  return shape;
}

}  // namespace pd
