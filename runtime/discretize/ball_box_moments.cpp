// Moments of a ball cut by a rectangle (derivation in ball_box_moments.hpp).
#include "discretize/ball_box_moments.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace pd {

namespace {
constexpr int kGaussPoints = 24;

// Gauss-Legendre nodes and weights on [-1, 1] by Golub-Welsch (eigen-decomposition of the
// Jacobi matrix of the Legendre recurrence).
struct GaussRule {
  std::vector<double> node, weight;
  GaussRule() {
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(kGaussPoints, kGaussPoints);
    for (int k = 1; k < kGaussPoints; ++k) J(k, k - 1) = J(k - 1, k) = k / std::sqrt(4.0 * k * k - 1);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(J);
    for (int k = 0; k < kGaussPoints; ++k) {
      node.push_back(eig.eigenvalues()[k]);
      weight.push_back(2 * std::pow(eig.eigenvectors()(0, k), 2));
    }
  }
};
const GaussRule& gauss() {
  static const GaussRule rule;
  return rule;
}
}  // namespace

bool ball_inside_box(double delta, const double* c, const Box2& box) {
  for (int a = 0; a < 2; ++a)
    if (c[a] - box.lo[a] < delta || box.hi[a] - c[a] < delta) return false;
  return true;
}

double ball_box_moment_2d(const BondMonomial& f, double delta, const double* c, const Box2& box) {
  const int p = f.degree() - f.inverse_r_power + 2;
  if (p <= 0)
    throw std::invalid_argument("ball_box_moment_2d: the integrand is not integrable at the origin");
  // Faces as (outward normal, distance from the centre).
  const double normal[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
  const double dist[4] = {c[0] - box.lo[0], box.hi[0] - c[0], c[1] - box.lo[1], box.hi[1] - c[1]};
  for (double d : dist)
    if (d < 0) throw std::invalid_argument("ball_box_moment_2d: the centre lies outside the box");
  // Breakpoints: where each face starts cutting the circle, and the corner directions.
  std::vector<double> breaks{0.0, 2 * M_PI};
  auto add = [&](double t) { breaks.push_back(std::fmod(t + 4 * M_PI, 2 * M_PI)); };
  for (int k = 0; k < 4; ++k)
    if (dist[k] < delta) {
      const double phi = std::atan2(normal[k][1], normal[k][0]), half = std::acos(dist[k] / delta);
      add(phi - half), add(phi + half);
    }
  for (double x : {box.lo[0], box.hi[0]})
    for (double y : {box.lo[1], box.hi[1]}) add(std::atan2(y - c[1], x - c[0]));
  std::sort(breaks.begin(), breaks.end());
  auto radius = [&](double ct, double st) {
    double R = delta;
    for (int k = 0; k < 4; ++k) {
      const double along = normal[k][0] * ct + normal[k][1] * st;
      if (along > 0) R = std::min(R, dist[k] / along);
    }
    return R;
  };
  const GaussRule& g = gauss();
  double sum = 0;
  for (std::size_t s = 0; s + 1 < breaks.size(); ++s) {
    const double a = breaks[s], b = breaks[s + 1], half = 0.5 * (b - a);
    if (half <= 0) continue;
    for (int k = 0; k < kGaussPoints; ++k) {
      const double t = a + half * (1 + g.node[k]), ct = std::cos(t), st = std::sin(t);
      const double R = radius(ct, st);
      const double n[2] = {ct, st};
      // The angular monomial n^b times the radial integral R^p / p.
      sum += g.weight[k] * half * f.value(2, n, 1.0) * std::pow(R, p) / p;
    }
  }
  return sum;
}

double ball_disk_shadow_moment_2d(const BondMonomial& f, double delta, const double* c, const double* disk,
                                  double a) {
  const int p = f.degree() - f.inverse_r_power + 2;
  if (p <= 0)
    throw std::invalid_argument("ball_disk_shadow_moment_2d: the integrand is not integrable at the origin");
  const double g[2] = {disk[0] - c[0], disk[1] - c[1]}, dist = std::hypot(g[0], g[1]);
  if (!(dist > a)) throw std::invalid_argument("ball_disk_shadow_moment_2d: the centre lies inside the disk");
  // R(t): delta, or the distance to the first crossing of the circle along n(t) when the
  // ray meets it. The near root of |s n - g| = a is s = g.n - sqrt((g.n)^2 - |g|^2 + a^2).
  auto radius = [&](double ct, double st) {
    const double gn = g[0] * ct + g[1] * st, disc = gn * gn - dist * dist + a * a;
    if (gn <= 0 || disc < 0) return delta;
    return std::min(delta, gn - std::sqrt(disc));
  };
  // Breakpoints: the two tangent directions (R jumps or has a square-root edge there) and
  // the directions of the points where the circle crosses the horizon (R has a kink).
  std::vector<double> breaks{0.0, 2 * M_PI};
  auto add = [&](double t) { breaks.push_back(std::fmod(t + 4 * M_PI, 2 * M_PI)); };
  const double phi = std::atan2(g[1], g[0]), half_shadow = std::asin(a / dist);
  add(phi - half_shadow), add(phi + half_shadow);
  // |y| = delta and |y - g| = a meet where y.g = (delta^2 + |g|^2 - a^2) / 2.
  const double cosine = (delta * delta + dist * dist - a * a) / (2 * delta * dist);
  if (std::fabs(cosine) < 1) add(phi - std::acos(cosine)), add(phi + std::acos(cosine));
  std::sort(breaks.begin(), breaks.end());
  const GaussRule& rule = gauss();
  double sum = 0;
  auto term = [&](double t) {
    const double n[2] = {std::cos(t), std::sin(t)};
    return f.value(2, n, 1.0) * std::pow(radius(n[0], n[1]), p) / p;
  };
  for (std::size_t s = 0; s + 1 < breaks.size(); ++s) {
    const double t0 = breaks[s], t1 = breaks[s + 1], quarter = 0.25 * (t1 - t0);
    if (quarter <= 0) continue;
    // The outer quarters in t = end -+ quarter v^2, which turns a square-root edge of R
    // at a tangent direction into a smooth function of v; the middle half plain.
    for (int k = 0; k < kGaussPoints; ++k) {
      const double v = 0.5 * (1 + rule.node[k]), dv = 0.5 * rule.weight[k];
      sum += dv * 2 * quarter * v * (term(t0 + quarter * v * v) + term(t1 - quarter * v * v));
      sum += dv * 2 * quarter * term(t0 + quarter * (1 + 2 * v));
    }
  }
  return sum;
}

}  // namespace pd
