// Least-norm, equality-constrained quadrature weights per family (eq. 2.12 of paper 001).
#include "discretize/obq_weights.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>
#include <optional>

namespace pd {

namespace {
// Relative pivot below which A is taken as rank deficient. The scaled matrix has entries
// of order one, so a genuinely unisolvent family sits many orders above it.
constexpr double kRankThreshold = 1e-10;

std::string where(int dim, const double* center) {
  return dim == 2 ? fmt::format("({:.6g}, {:.6g})", center[0], center[1])
                  : fmt::format("({:.6g}, {:.6g}, {:.6g})", center[0], center[1], center[2]);
}
}  // namespace

std::vector<double> obq_family_weights(const ReproducingSpace& space, const double* xi, int n, double delta,
                                       int particle, const double* center, const Box2* body) {
  const int dim = space.dim;
  // Cut ball: the moments of the unit ball about center/delta in the body scaled by 1/delta.
  const bool cut = body && dim == 2 && !ball_inside_box(delta, center, *body);
  const double unit_center[2] = {cut ? center[0] / delta : 0, cut ? center[1] / delta : 0};
  Box2 unit_body;
  if (cut)
    for (int a = 0; a < 2; ++a) unit_body.lo[a] = body->lo[a] / delta, unit_body.hi[a] = body->hi[a] / delta;
  return obq_family_weights_over(space, xi, n, delta, particle, center, [&](const BondMonomial& f) {
    return cut ? ball_box_moment_2d(f, 1.0, unit_center, unit_body) : ball_moment(dim, f, 1.0);
  });
}

std::vector<double> obq_family_weights_over(const ReproducingSpace& space, const double* xi, int n,
                                            double delta, int particle, const double* center,
                                            const std::function<double(const BondMonomial&)>& unit_moment) {
  const int dim = space.dim;
  const int m = static_cast<int>(space.terms.size());
  // Scaled bonds xi/delta keep A of order one at any h: sum_j f(xi_j/delta) omega_j
  // = delta^d I_unit[f] for a monomial f (the delta^(|b|-s) of both sides cancels).
  Eigen::MatrixXd At(n, m);  // A^T: row j is bond j
  Eigen::VectorXd b(m);
  for (int t = 0; t < m; ++t) {
    b[t] = 0;
    for (const auto& [c, f] : weighted_term(space, space.terms[t]))
      b[t] += c * std::pow(delta, dim) * unit_moment(f);
  }
  for (int j = 0; j < n; ++j) {
    double scaled[3] = {0, 0, 0};
    double r2 = 0;
    for (int c = 0; c < dim; ++c) {
      scaled[c] = xi[j * dim + c] / delta;
      r2 += scaled[c] * scaled[c];
    }
    const double r = std::sqrt(r2);
    const double w = radial_weight(space, r);  // r is |xi|/delta here
    for (int t = 0; t < m; ++t) At(j, t) = w * space.terms[t].value(dim, scaled, r);
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(At);
  qr.setThreshold(kRankThreshold);
  if (n < m || qr.rank() < m)
    throw NotUnisolventError(
        particle,
        fmt::format("particle {} at {}: its family of {} bonds is not unisolvent for the reproducing "
                    "space '{}' ({} functions, rank {}); widen the horizon or perturb the points",
                    particle, where(dim, center), n, space.name, m, n < m ? n : qr.rank()));
  // A^T P = Q R, so A = P R^T Q^T; the least-norm solution of A omega = b is
  // omega = Q_m z with R^T z = P^T b.
  const Eigen::MatrixXd R = qr.matrixR().topLeftCorner(m, m).triangularView<Eigen::Upper>();
  const Eigen::VectorXd rhs = qr.colsPermutation().transpose() * b;
  Eigen::VectorXd z = R.transpose().triangularView<Eigen::Lower>().solve(rhs);
  Eigen::VectorXd padded = Eigen::VectorXd::Zero(n);
  padded.head(m) = z;
  const Eigen::VectorXd omega = qr.householderQ() * padded;
  return {omega.data(), omega.data() + n};
}

namespace {
// The family loop of both entry points. A family not needed, or (with `fall_back`) not
// unisolvent, keeps its neighbours' volumes; without `fall_back` the lowest
// non-unisolvent particle's error is rethrown (the same at any thread count).
CloudWeights weigh_families(const Particles& particles, const Bonds& bonds, const ReproducingSpace& space,
                            const std::vector<char>& needed, bool fall_back, const Box2* body) {
  if (space.dim != bonds.dim)
    throw std::invalid_argument("obq_weights: the space and the bonds differ in dimension");
  if (!needed.empty() && static_cast<int>(needed.size()) != bonds.particle_count())
    throw std::invalid_argument("obq_weights: one `needed` flag per particle expected");
  CloudWeights out;
  out.weights.assign(bonds.neighbor.size(), 0.0);
  const int n = bonds.particle_count();
  std::vector<char> volume(n, 0);
  std::optional<NotUnisolventError> first_error;
#pragma omp parallel for schedule(dynamic, 64)
  for (int p = 0; p < n; ++p) {
    const int begin = bonds.offsets[p];
    bool use_volume = !needed.empty() && !needed[p];
    if (!use_volume) try {
        const std::vector<double> w =
            obq_family_weights(space, bonds.xi.data() + static_cast<std::ptrdiff_t>(begin) * bonds.dim,
                               bonds.family_size(p), bonds.delta[p], p, particles.position(p), body);
        std::copy(w.begin(), w.end(), out.weights.begin() + begin);
      } catch (const NotUnisolventError& e) {
        volume[p] = 1;
        use_volume = true;
        if (!fall_back) {
#pragma omp critical(obq_first_error)
          if (!first_error || e.particle() < first_error->particle()) first_error = e;
        }
      }
    if (use_volume)
      for (int b = begin; b < bonds.offsets[p + 1]; ++b) out.weights[b] = particles.volume[bonds.neighbor[b]];
  }
  if (first_error) throw *first_error;
  for (int p = 0; p < n; ++p)
    if (volume[p]) {
      if (out.first_volume_family < 0) out.first_volume_family = p;
      ++out.volume_families;
    }
  return out;
}
}  // namespace

std::vector<double> obq_weights(const Particles& particles, const Bonds& bonds, const ReproducingSpace& space,
                                const std::vector<char>& needed) {
  return weigh_families(particles, bonds, space, needed, false, nullptr).weights;
}

CloudWeights obq_weights_where_unisolvent(const Particles& particles, const Bonds& bonds,
                                          const ReproducingSpace& space, const Box2* body) {
  return weigh_families(particles, bonds, space, {}, true, body);
}

}  // namespace pd
