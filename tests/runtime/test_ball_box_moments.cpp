// Moments of a ball cut by the faces of a box (ball_box_moments.hpp): closed forms for a
// disc cut by one line, the uncut ball's closed form, and a brute-force integration over
// the polar angle (a fine trapezoid rule that knows nothing of the face angles).
#include <gtest/gtest.h>

#include <cmath>

#include "discretize/ball_box_moments.hpp"
#include "discretize/reproducing_space.hpp"

namespace {
const pd::Box2 kUnitBox{{0, 0}, {1, 1}};

// int_0^{2 pi} n^b R(t)^p / p dt with R from a direct ray-box intersection, by the
// trapezoid rule on `steps` intervals (error O(steps^-2) at the kinks of R).
double brute_force(const pd::BondMonomial& f, double delta, const double* c, const pd::Box2& box, int steps) {
  const int p = f.degree() - f.inverse_r_power + 2;
  double sum = 0;
  for (int k = 0; k < steps; ++k) {
    const double t = 2 * M_PI * k / steps, n[2] = {std::cos(t), std::sin(t)};
    double R = delta;
    for (int a = 0; a < 2; ++a) {
      if (n[a] > 0) R = std::min(R, (box.hi[a] - c[a]) / n[a]);
      if (n[a] < 0) R = std::min(R, (box.lo[a] - c[a]) / n[a]);
    }
    sum += f.value(2, n, 1.0) * std::pow(R, p) / p;
  }
  return sum * 2 * M_PI / steps;
}
}  // namespace

TEST(BallBoxMoments, AnUncutBallHasTheClosedFormMoments) {
  const double c[2] = {0.5, 0.5};
  for (const pd::BondMonomial& f : pd::paper001_odd_space(2).terms)
    EXPECT_NEAR(pd::ball_box_moment_2d(f, 0.3, c, kUnitBox), pd::ball_moment(2, f, 0.3), 1e-14);
  EXPECT_TRUE(pd::ball_inside_box(0.3, c, kUnitBox));
  EXPECT_FALSE(pd::ball_inside_box(0.6, c, kUnitBox));
}

TEST(BallBoxMoments, ADiscCutByOneFaceHasTheSegmentFormulas) {
  // Centre at depth d above the bottom face: the disc minus the cap below y = -d.
  const double delta = 0.2, d = 0.07, c[2] = {0.5, d};
  const double s = std::sqrt(delta * delta - d * d);
  const double area = delta * delta * (M_PI - std::acos(d / delta)) + d * s;
  EXPECT_NEAR(pd::ball_box_moment_2d({{0, 0, 0}, 0}, delta, c, kUnitBox), area, 1e-15);
  // int y dA over the region = -(int over the cap) = (2/3) (delta^2 - d^2)^(3/2).
  EXPECT_NEAR(pd::ball_box_moment_2d({{0, 1, 0}, 0}, delta, c, kUnitBox), 2.0 / 3.0 * s * s * s, 1e-15);
  EXPECT_NEAR(pd::ball_box_moment_2d({{1, 0, 0}, 0}, delta, c, kUnitBox), 0.0, 1e-15);
}

TEST(BallBoxMoments, CutBallsMatchABruteForceAngularIntegration) {
  // One face, two faces (a corner) and a ball larger than the box's half width.
  const double centres[3][2] = {{0.5, 0.05}, {0.04, 0.11}, {0.3, 0.6}};
  const double deltas[3] = {0.2, 0.2, 0.45};
  for (int k = 0; k < 3; ++k)
    for (const pd::BondMonomial& f : pd::paper001_odd_space(2).terms) {
      const double exact = pd::ball_box_moment_2d(f, deltas[k], centres[k], kUnitBox);
      const double brute = brute_force(f, deltas[k], centres[k], kUnitBox, 400000);
      EXPECT_NEAR(exact, brute, 1e-10 * std::pow(deltas[k], f.degree() - f.inverse_r_power + 2))
          << "centre " << k << ", b = (" << f.powers[0] << ", " << f.powers[1]
          << "), s = " << f.inverse_r_power;
    }
}

TEST(BallBoxMoments, ACentreOutsideTheBoxIsRefused) {
  const double c[2] = {-0.1, 0.5};
  EXPECT_THROW(pd::ball_box_moment_2d({{0, 0, 0}, 0}, 0.2, c, kUnitBox), std::invalid_argument);
}
