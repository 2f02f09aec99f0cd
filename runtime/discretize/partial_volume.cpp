// Volume factors: the linear reduction of eq. (2.16), and the exact cell-horizon
// intersection: the 2D cell-disc area here, the 3D cell-ball volume in closed form
// (cell_ball_volume.hpp; paper 002's adaptive integration, ai_volume.hpp, is kept for
// studies of it, not used here).
#include "discretize/partial_volume.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "discretize/cell_ball_volume.hpp"
#include "discretize/discretization.hpp"

namespace pd {

double linear_volume_factor(double r, double delta, double h) {
  if (r <= delta - 0.5 * h) return 1.0;
  if (r <= delta + 0.5 * h) return (delta + 0.5 * h - r) / h;
  return 0.0;
}

namespace {
// Antiderivative of the half chord g(x) = sqrt(R^2 - x^2) on |x| <= R.
double half_chord_integral(double x, double R) {
  x = std::clamp(x, -R, R);
  return 0.5 * (x * std::sqrt(std::max(0.0, R * R - x * x)) + R * R * std::asin(x / R));
}

// Integral over [a, b] of clamp(g(x), lo, hi), g the half chord (0 outside |x| <= R).
// Between the breakpoints (g = lo, g = hi, x = +-R, and x = 0 where g peaks, so that g is
// monotone on each piece and its midpoint tells the regime even when a level equals R)
// the integrand is a constant or g.
double clamped_chord_integral(double a, double b, double lo, double hi, double R) {
  if (b <= a) return 0.0;
  std::vector<double> cuts{a, b};
  for (double level : {lo, hi})
    if (level > 0 && level < R)
      for (double s : {-1.0, 1.0}) cuts.push_back(s * std::sqrt(R * R - level * level));
  cuts.push_back(-R), cuts.push_back(R), cuts.push_back(0.0);
  std::sort(cuts.begin(), cuts.end());
  double sum = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double x0 = std::max(a, cuts[i]), x1 = std::min(b, cuts[i + 1]);
    if (x1 <= x0) continue;
    const double xm = 0.5 * (x0 + x1);
    const double g = std::fabs(xm) < R ? std::sqrt(R * R - xm * xm) : 0.0;
    if (g <= lo)
      sum += lo * (x1 - x0);
    else if (g >= hi)
      sum += hi * (x1 - x0);
    else
      sum += half_chord_integral(x1, R) - half_chord_integral(x0, R);
  }
  return sum;
}
}  // namespace

double cell_disc_area(double cx, double cy, double delta, double h) {
  const double x0 = cx - 0.5 * h, x1 = cx + 0.5 * h, y0 = cy - 0.5 * h, y1 = cy + 0.5 * h;
  const double a = std::max(x0, -delta), b = std::min(x1, delta);
  // Height of the cell inside the disc at x: clamp(g) - clamp(-g) = clamp(g) + clamp'(g)
  // with clamp(-g, y0, y1) = -clamp(g, -y1, -y0).
  return clamped_chord_integral(a, b, y0, y1, delta) + clamped_chord_integral(a, b, -y1, -y0, delta);
}

double cell_distance(const double* c, int dim, double h) {
  double d2 = 0;
  for (int i = 0; i < dim; ++i) {
    const double gap = std::max(0.0, std::fabs(c[i]) - 0.5 * h);
    d2 += gap * gap;
  }
  return std::sqrt(d2);
}

double quadrature_reach(Quadrature q, double delta, double h, int dim) {
  switch (q) {
    case Quadrature::Volume:
    case Quadrature::Obq:
    case Quadrature::ObqCut:
      return delta;
    case Quadrature::PartialLinear:
      return delta + 0.5 * h;
    case Quadrature::PartialExact:
      return delta + 0.5 * h * std::sqrt(static_cast<double>(dim));
  }
  return delta;
}

double volume_factor(Quadrature q, const double* xi, int dim, double delta, double h) {
  double r2 = 0;
  for (int i = 0; i < dim; ++i) r2 += xi[i] * xi[i];
  const double r = std::sqrt(r2);
  switch (q) {
    case Quadrature::Volume:
    case Quadrature::Obq:
    case Quadrature::ObqCut:
      return r <= delta * (1 + 1e-12) ? 1.0 : 0.0;
    case Quadrature::PartialLinear:
      return linear_volume_factor(r, delta, h);
    case Quadrature::PartialExact:
      if (cell_distance(xi, dim, h) >= delta) return 0.0;
      if (dim == 2) return cell_disc_area(xi[0], xi[1], delta, h) / (h * h);
      if (dim == 3) return cell_ball_volume(xi, delta, h) / (h * h * h);
      return 1.0;
  }
  return 1.0;
}

Bonds find_quadrature_bonds(const Particles& p, double delta, double h, Quadrature q,
                            double (*influence)(double, double)) {
  // OBQ weights replace the volumes of the centre-inclusion bonds (assembly/collocation.hpp).
  if (q == Quadrature::Volume || is_obq(q)) return find_bonds(p, delta, influence);
  const int d = p.dim;
  Bonds all = find_bonds(p, quadrature_reach(q, delta, h, d), influence);
  Bonds b;
  b.dim = d;
  b.offsets.assign(all.offsets.size(), 0);
  b.delta.assign(all.delta.size(), delta);
  for (int i = 0; i < all.particle_count(); ++i) {
    for (int k = all.offsets[i]; k < all.offsets[i + 1]; ++k) {
      const double* xi = all.xi.data() + static_cast<std::size_t>(k) * d;
      const double f = volume_factor(q, xi, d, delta, h);
      if (f <= 0.0) continue;
      b.neighbor.push_back(all.neighbor[k]);
      for (int c = 0; c < d; ++c) b.xi.push_back(xi[c]);
      b.length.push_back(all.length[k]);
      b.w.push_back(influence(std::min(all.length[k], delta), delta));
      b.alpha.push_back(1.0);
      b.volume_factor.push_back(f);
    }
    b.offsets[i + 1] = static_cast<int>(b.neighbor.size());
  }
  return b;
}

}  // namespace pd
