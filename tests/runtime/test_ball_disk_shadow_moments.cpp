// The moments of the part of a ball that its centre sees past a disk (Fig. 1's hole):
// against the same integral taken in the other order, radius outside and angle inside,
// where at radius r the hidden directions form one arc about the disk's direction of
// half-width h(r): 0 before the disk, the directions in which the circle of radius r
// is inside the disk (|r n - g| <= a) up to the tangent length L = sqrt(|g|^2 - a^2), and
// the whole tangent cone asin(a/|g|) beyond it. No breakpoint of the angular method is
// shared, and h(r) is continuous, so Gauss-Legendre on panels converges.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "discretize/ball_box_moments.hpp"
#include "polar_quadrature.hpp"

namespace {
double reference(const pd::BondMonomial& f, double delta, const double* c, const double* disk, double a) {
  std::vector<double> x, w;
  pd_test::gauss_legendre(40, x, w);  // Newton on P_n: not the library's Golub-Welsch rule
  const double g[2] = {disk[0] - c[0], disk[1] - c[1]}, dist = std::hypot(g[0], g[1]),
               phi = std::atan2(g[1], g[0]);
  const double L = std::sqrt(dist * dist - a * a);
  auto half_width = [&](double r) {
    if (r <= dist - a) return 0.0;
    if (r >= L) return std::asin(a / dist);
    return std::acos(std::clamp((r * r + dist * dist - a * a) / (2 * r * dist), -1.0, 1.0));
  };
  auto hidden = [&](double h) {  // int of n^b over [phi - h, phi + h]
    double s = 0;
    for (int k = 0; k < 40; ++k) {
      const double t = phi + h * x[k], n[2] = {std::cos(t), std::sin(t)};
      s += h * w[k] * f.value(2, n, 1.0);
    }
    return s;
  };
  const double full = pd::sphere_monomial_integral(2, f.powers);
  const int q = f.degree() - f.inverse_r_power + 1;
  std::vector<double> cuts{0, std::min(delta, dist - a), std::min(delta, L), delta};
  double sum = 0;
  for (std::size_t s = 0; s + 1 < cuts.size(); ++s)
    for (int panel = 0; panel < 50; ++panel) {  // h(r) has a square-root edge at dist - a
      const double lo = cuts[s] + (cuts[s + 1] - cuts[s]) * std::pow(panel / 50.0, 2);
      const double hi = cuts[s] + (cuts[s + 1] - cuts[s]) * std::pow((panel + 1) / 50.0, 2);
      for (int k = 0; k < 40; ++k) {
        const double r = 0.5 * (lo + hi) + 0.5 * (hi - lo) * x[k];
        sum += 0.5 * (hi - lo) * w[k] * std::pow(r, q) * (full - hidden(half_width(r)));
      }
    }
  return sum;
}
}  // namespace

TEST(BallDiskShadowMoments, EqualTheRadialFirstIntegral) {
  const double c[2] = {0.1, -0.2};
  struct Case {
    double disk[2], a, delta;
  };
  // The disk inside the horizon; crossing it (tangent points inside and outside); beyond it.
  const Case cases[] = {
      {{0.6, 0.3}, 0.25, 1.5}, {{0.9, 0.1}, 0.5, 1.0}, {{-0.7, -1.1}, 0.9, 1.2}, {{0.4, 0.2}, 0.05, 0.6}};
  for (const Case& k : cases)
    for (const auto& f :
         {pd::BondMonomial{{0, 0, 0}, 0}, pd::BondMonomial{{1, 0, 0}, 0}, pd::BondMonomial{{2, 1, 0}, 0},
          pd::BondMonomial{{3, 0, 0}, 3}, pd::BondMonomial{{2, 2, 0}, 3}, pd::BondMonomial{{1, 3, 0}, 3},
          pd::BondMonomial{{0, 4, 0}, 3}}) {
      const double got = pd::ball_disk_shadow_moment_2d(f, k.delta, c, k.disk, k.a);
      const double ref = reference(f, k.delta, c, k.disk, k.a);
      const double scale = std::pow(k.delta, f.degree() - f.inverse_r_power + 2);
      EXPECT_NEAR(got, ref, 1e-11 * scale)
          << "disk (" << k.disk[0] << ", " << k.disk[1] << ") a " << k.a << " powers " << f.powers[0]
          << f.powers[1] << " s " << f.inverse_r_power;
    }
}

TEST(BallDiskShadowMoments, ADiskBeyondTheHorizonLeavesTheWholeBall) {
  const double c[2] = {0, 0}, disk[2] = {3, 1};
  for (const auto& f : {pd::BondMonomial{{0, 0, 0}, 0}, pd::BondMonomial{{2, 2, 0}, 3}})
    EXPECT_NEAR(pd::ball_disk_shadow_moment_2d(f, 1.0, c, disk, 0.5), pd::ball_moment(2, f, 1.0), 1e-14);
}
