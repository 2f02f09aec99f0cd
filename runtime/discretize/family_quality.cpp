// Weighted volumes and shape-tensor conditioning of every family.
#include "discretize/family_quality.hpp"

#include <fmt/core.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "input/yaml_keys.hpp"  // SceneError

namespace pd {

double continuum_weighted_volume(double (*influence)(double, double), double delta, int dim) {
  // Midpoint rule in r: w r^(d+1) is integrable even for w ~ 1/r^2 (rational n = 2), and
  // the midpoints never touch r = 0 where such w is infinite. A threshold needs no more.
  const int n = 2000;
  double sum = 0;
  for (int k = 0; k < n; ++k) {
    const double r = (k + 0.5) * delta / n;
    sum += influence(r, delta) * std::pow(r, dim + 1);
  }
  return (dim == 2 ? 2 * M_PI : 4 * M_PI) * sum * delta / n;
}

namespace {
struct Family {
  int particle;
  double value;
};

std::string describe(const Particles& p, const Bonds& b, const std::vector<Family>& bad, const char* what) {
  std::string s;
  const std::size_t shown = std::min<std::size_t>(bad.size(), 5);
  for (std::size_t k = 0; k < shown; ++k) {
    const int q = bad[k].particle;
    int intact = 0;
    for (int e = b.offsets[q]; e < b.offsets[q + 1]; ++e) intact += b.alpha[e] != 0.0;
    const double* x = p.position(q);
    s += fmt::format("{}particle {} at ({:.6g}, {:.6g}{}) {} {:.3g}, {} intact bond(s)", k ? "; " : "", q,
                     x[0], x[1], p.dim == 3 ? fmt::format(", {:.6g}", x[2]) : "", what, bad[k].value, intact);
  }
  if (bad.size() > shown) s += fmt::format("; and {} more", bad.size() - shown);
  return s;
}

// The largest side of the particles' bounding box: a horizon beyond it cuts every family
// by the boundary, and "increase the horizon ratio" would only make that worse.
double largest_extent(const Particles& p) {
  double extent = 0;
  for (int r = 0; r < p.dim && p.size() > 0; ++r) {
    double lo = p.position(0)[r], hi = lo;
    for (int q = 1; q < p.size(); ++q)
      lo = std::min(lo, p.position(q)[r]), hi = std::max(hi, p.position(q)[r]);
    extent = std::max(extent, hi - lo);
  }
  return extent;
}
}  // namespace

FamilyQualityReport check_family_quality(const Particles& p, const Bonds& b,
                                         double (*influence)(double, double),
                                         const std::string& influence_name, double h,
                                         const FamilyQualityLimits& limits) {
  const int n = p.size(), d = p.dim;
  std::vector<Family> light, singular;
  FamilyQualityReport report;
  report.worst_weighted_volume_ratio = std::numeric_limits<double>::infinity();
  double cached_delta = -1, m_continuum = 0;
  for (int q = 0; q < n; ++q) {
    if (b.delta[q] != cached_delta)
      cached_delta = b.delta[q], m_continuum = continuum_weighted_volume(influence, cached_delta, d);
    Eigen::Matrix3d K = Eigen::Matrix3d::Zero();
    bool finite = true;
    for (int e = b.offsets[q]; e < b.offsets[q + 1]; ++e) {
      const double f = b.alpha[e] * b.w[e] * p.volume[b.neighbor[e]];
      finite = finite && std::isfinite(f);
      for (int r = 0; r < d; ++r)
        for (int c = 0; c < d; ++c)
          K(r, c) +=
              f * b.xi[static_cast<std::size_t>(e) * d + r] * b.xi[static_cast<std::size_t>(e) * d + c];
    }
    const double ratio = finite ? K.trace() / m_continuum : std::numeric_limits<double>::quiet_NaN();
    if (!(ratio >= limits.min_weighted_volume_ratio)) {
      light.push_back({q, ratio});
      continue;  // a family without weight has no meaningful shape tensor either
    }
    if (ratio < report.worst_weighted_volume_ratio)
      report.worst_weighted_volume_ratio = ratio, report.worst_weighted_volume_particle = q;
    const Eigen::VectorXd eig =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K.topLeftCorner(d, d)).eigenvalues();
    const double condition = eig[0] > 0 ? eig[d - 1] / eig[0] : std::numeric_limits<double>::infinity();
    if (condition > report.worst_condition)
      report.worst_condition = condition, report.worst_condition_particle = q;
    if (condition > limits.max_shape_condition) singular.push_back({q, condition});
  }
  const double delta = n > 0 ? b.delta[0] : 0;
  if (!light.empty() && delta > largest_extent(p))  // bad input (exit 2), like a key out of range
    throw SceneError(
        fmt::format("the horizon delta = {:.6g} exceeds the body (its particles span at most {:.6g}): {} "
                    "particle(s) have "
                    "(almost) no weighted volume, a family being cut by the boundary in every direction: {}; "
                    "reduce the horizon "
                    "(horizon.ratio or horizon.length) below the body's size",
                    delta, largest_extent(p), light.size(), describe(p, b, light, "ratio")));
  // The scene's horizon, influence or geometry: bad input (exit 2), like the above.
  if (!light.empty())
    throw SceneError(
        fmt::format("{} particle(s) have (almost) no weighted volume: sum w |xi|^2 V is below {:g} of a full "
                    "horizon's with influence "
                    "{} at delta/h = {:.4g} (near delta/h = 1 the only bonds lie at r = delta, where many "
                    "influence functions vanish; "
                    "a particle whose bonds are all cut has none): {}; "
                    "increase the horizon ratio or choose another influence function",
                    light.size(), limits.min_weighted_volume_ratio, influence_name, delta / h,
                    describe(p, b, light, "ratio")));
  if (!singular.empty())
    throw SceneError(fmt::format(
        "{} particle(s) have a near-singular shape tensor sum w xi (x) xi V (condition number above {:g}; "
        "influence {}, "
        "delta/h = {:.4g}): their bonds do not span every direction, so the deformation gradient and the "
        "stiffness are "
        "undetermined: {}; increase the horizon ratio, or check cracks and thin parts of the geometry",
        singular.size(), limits.max_shape_condition, influence_name, delta / h,
        describe(p, b, singular, "condition number")));
  return report;
}

}  // namespace pd
