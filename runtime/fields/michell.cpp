// The Michell hole field (michell.hpp); the formulas are paper 001 eqs. 4.5-4.6, which
// match the classical Kirsch solution (e.g. Barber, Elasticity, §8.4.1) term by term.
#include "fields/michell.hpp"

#include <cmath>

namespace pd {

std::array<double, 2> MichellHole::displacement(double x, double y) const {
  const double dx = x - x0, dy = y - y0, r = std::hypot(dx, dy);
  if (r == 0) return {0.0, 0.0};
  const double t = std::atan2(dy, dx), k = kappa(), s = a / r, s3 = s * s * s;
  const double c = T * a / (8 * mu);
  const double ux = c * ((r / a) * (k + 1) * std::cos(t) + 2 * s * ((1 + k) * std::cos(t) + std::cos(3 * t)) -
                         2 * s3 * std::cos(3 * t));
  const double uy = c * ((r / a) * (k - 3) * std::sin(t) + 2 * s * ((1 - k) * std::sin(t) + std::sin(3 * t)) -
                         2 * s3 * std::sin(3 * t));
  return {ux, uy};
}

std::array<double, 3> MichellHole::stress(double x, double y) const {
  const double dx = x - x0, dy = y - y0, r = std::hypot(dx, dy);
  const double t = std::atan2(dy, dx), s2 = a * a / (r * r), s4 = s2 * s2;
  const double c2 = std::cos(2 * t), c4 = std::cos(4 * t), n2 = std::sin(2 * t), n4 = std::sin(4 * t);
  return {T * (1 - s2 * (1.5 * c2 + c4) + 1.5 * s4 * c4), T * (-s2 * (0.5 * c2 - c4) - 1.5 * s4 * c4),
          T * (-s2 * (0.5 * n2 + n4) + 1.5 * s4 * n4)};
}

}  // namespace pd
