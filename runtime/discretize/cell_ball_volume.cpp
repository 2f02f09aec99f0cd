// Cell-ball intersection volume by inclusion-exclusion of closed-form corner volumes
// (derivation in cell_ball_volume.hpp).
#include "discretize/cell_ball_volume.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pd {

namespace {
constexpr double kPi = std::numbers::pi;

// F(a, b, c) for a, b, c >= 0: int_a^X q(x) dx evaluated from the antiderivatives
//   int ρ^2 asin(k/ρ) dx = P(x) atan2(k, s) - (2R^3/3) atan2(k x, R s)
//                          + k (3R^2 + k^2)/6 atan2(x, s) + k x s / 6,
//   int sqrt(ρ^2 - k^2) dx = (x s + (R^2 - k^2) atan2(x, s)) / 2,
// with P(x) = R^2 x - x^3/3 and s = sqrt(R^2 - k^2 - x^2). At x = X the P terms cancel
// (atan2(b, c) + atan2(c, b) = π/2) and s is c for k = b and b for k = c; what is left is
// `upper`. atan2 rather than asin keeps each angle accurate where its sine is near 1.
double corner_volume_nonneg(double a, double b, double c, double R) {
  const double R2 = R * R;
  if (a * a + b * b + c * c >= R2) return 0.0;
  const double X = std::sqrt(R2 - b * b - c * c);
  const double sb = std::sqrt(R2 - a * a - b * b), sc = std::sqrt(R2 - a * a - c * c);
  const double R3 = R2 * R, P = a * (R2 - a * a / 3);
  const double wb = b * (3 * R2 - b * b) / 6, wc = c * (3 * R2 - c * c) / 6;
  // Tends to π/2 as (b, c) -> 0 from any direction; atan2(0, 0) would give 0.
  const double pair = (b == 0 && c == 0) ? kPi / 2 : std::atan2(b * X, R * c) + std::atan2(c * X, R * b);
  const double upper = R3 / 3 * pair - wb * std::atan2(X, c) - wc * std::atan2(X, b) + b * c * X / 3;
  const double lower = P / 2 * (std::atan2(b, sb) + std::atan2(c, sc) - kPi / 2) -
                       R3 / 3 * (std::atan2(a * b, R * sb) + std::atan2(a * c, R * sc)) +
                       wb * std::atan2(a, sb) + wc * std::atan2(a, sc) + a / 3 * (b * sb + c * sc) -
                       a * b * c;
  return upper + lower;
}

// The ball beyond the plane z = c: one polynomial on all of [-R, R] (no reflection, so no
// whole-ball term to cancel for c < 0).
double cap_volume(double c, double R) {
  c = std::clamp(c, -R, R);
  return kPi * (R - c) * (R - c) * (2 * R + c) / 3;
}

// The ball beyond the edge {y > b, z > c}: reflect a negative coordinate, then the two
// octants x > 0 and x < 0 are mirror images.
double edge_volume(double b, double c, double R) {
  if (b < 0) return cap_volume(c, R) - edge_volume(-b, c, R);
  if (c < 0) return cap_volume(b, R) - edge_volume(b, -c, R);
  return 2 * corner_volume_nonneg(0, b, c, R);
}

// F(a, b, c) for any signs: {x > a} = everything minus the mirror image of {x > -a}.
double corner_volume(double a, double b, double c, double R) {
  if (a < 0) return edge_volume(b, c, R) - corner_volume(-a, b, c, R);
  if (b < 0) return edge_volume(a, c, R) - corner_volume(a, -b, c, R);
  if (c < 0) return edge_volume(a, b, R) - corner_volume(a, b, -c, R);
  return corner_volume_nonneg(a, b, c, R);
}
}  // namespace

double cell_ball_volume(const double* c, double delta, double h) {
  const double R = delta, cell = h * h * h;
  if (R <= 0 || h <= 0) return 0.0;
  // Reflect the cell into the positive octant (the ball is symmetric): then its upper
  // faces are positive and a lower face is negative only when the cell straddles the axis,
  // which keeps the reflections in corner_volume (each one more evaluation) few.
  double lo[3], hi[3], near2 = 0, far2 = 0;
  bool holds_ball = true;
  for (int i = 0; i < 3; ++i) {
    const double m = std::fabs(c[i]);
    lo[i] = m - 0.5 * h, hi[i] = m + 0.5 * h;
    const double gap = std::max(0.0, lo[i]);
    near2 += gap * gap, far2 += hi[i] * hi[i];
    holds_ball = holds_ball && lo[i] <= -R && hi[i] >= R;
  }
  if (near2 >= R * R) return 0.0;
  if (far2 <= R * R) return cell;
  if (holds_ball) return 4.0 / 3.0 * kPi * R * R * R;
  double sum = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const bool ux = corner & 1, uy = corner & 2, uz = corner & 4;
    const double f = corner_volume(ux ? hi[0] : lo[0], uy ? hi[1] : lo[1], uz ? hi[2] : lo[2], R);
    sum += ((ux + uy + uz) % 2 ? -f : f);
  }
  return std::clamp(sum, 0.0, cell);
}

}  // namespace pd
