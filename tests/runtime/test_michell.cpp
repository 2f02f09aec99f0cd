// The Michell hole field of paper 001 §4.2 against its closed-form stress: Hooke's law on
// finite differences of the displacement gives the Kirsch stress, that stress is in
// equilibrium (finite differences of div sigma), the hole surface is traction-free and the
// far field is the uniform tension with its plane-strain uniform strain.
#include <gtest/gtest.h>

#include <cmath>

#include "fields/analytic.hpp"
#include "fields/michell.hpp"

namespace {
// Plane strain, E = 1, nu = 0.3 (kappa = 1.8), and nu = 0.495 (near incompressible).
pd::MichellHole hole(double nu) {
  pd::MichellHole m;
  m.T = 0.7, m.a = 0.2, m.x0 = 0.5, m.y0 = 0.4;
  m.lambda = nu / ((1 + nu) * (1 - 2 * nu));
  m.mu = 1 / (2 * (1 + nu));
  return m;
}
// Points outside the hole at several radii and angles (no symmetry axis).
template <class F>
void for_points(const pd::MichellHole& m, F f) {
  for (double rr : {1.05, 1.5, 3.0})
    for (double t : {0.1, 0.9, 2.0, 3.3, 4.4, 5.9})
      f(m.x0 + rr * m.a * std::cos(t), m.y0 + rr * m.a * std::sin(t));
}
}  // namespace

TEST(Michell, HookesLawOnTheDisplacementGivesTheKirschStress) {
  for (double nu : {0.3, 0.495}) {
    const pd::MichellHole m = hole(nu);
    const double e = 1e-6;
    for_points(m, [&](double x, double y) {
      const auto xp = m.displacement(x + e, y), xm = m.displacement(x - e, y);
      const auto yp = m.displacement(x, y + e), ym = m.displacement(x, y - e);
      const double exx = (xp[0] - xm[0]) / (2 * e), eyy = (yp[1] - ym[1]) / (2 * e);
      const double exy = ((yp[0] - ym[0]) + (xp[1] - xm[1])) / (4 * e);
      const auto s = m.stress(x, y);
      const double tol = 1e-7 * m.T;
      EXPECT_NEAR(m.lambda * (exx + eyy) + 2 * m.mu * exx, s[0], tol) << nu << " " << x << " " << y;
      EXPECT_NEAR(m.lambda * (exx + eyy) + 2 * m.mu * eyy, s[1], tol) << nu << " " << x << " " << y;
      EXPECT_NEAR(2 * m.mu * exy, s[2], tol) << nu << " " << x << " " << y;
    });
  }
}

TEST(Michell, StressIsInEquilibrium) {
  const pd::MichellHole m = hole(0.3);
  const double e = 1e-5;
  for_points(m, [&](double x, double y) {
    const auto xp = m.stress(x + e, y), xm = m.stress(x - e, y), yp = m.stress(x, y + e),
               ym = m.stress(x, y - e);
    // div sigma = (d sxx/dx + d sxy/dy, d sxy/dx + d syy/dy)
    EXPECT_NEAR((xp[0] - xm[0]) / (2 * e) + (yp[2] - ym[2]) / (2 * e), 0.0, 1e-7 * m.T / m.a);
    EXPECT_NEAR((xp[2] - xm[2]) / (2 * e) + (yp[1] - ym[1]) / (2 * e), 0.0, 1e-7 * m.T / m.a);
  });
}

TEST(Michell, HoleSurfaceIsTractionFreeAndHoopStressPeaksAtThreeT) {
  const pd::MichellHole m = hole(0.3);
  for (int k = 0; k < 24; ++k) {
    const double t = 2 * M_PI * (k + 0.3) / 24, n[2] = {std::cos(t), std::sin(t)};
    const auto s = m.stress(m.x0 + m.a * n[0], m.y0 + m.a * n[1]);
    EXPECT_NEAR(s[0] * n[0] + s[2] * n[1], 0.0, 1e-14);
    EXPECT_NEAR(s[2] * n[0] + s[1] * n[1], 0.0, 1e-14);
  }
  // Kirsch's stress concentration: s_xx = 3T at the top of the hole, -T hoop at its side.
  EXPECT_NEAR(m.stress(m.x0, m.y0 + m.a)[0], 3 * m.T, 1e-14);
  EXPECT_NEAR(m.stress(m.x0 + m.a, m.y0)[1], -m.T, 1e-14);
}

TEST(Michell, FarFieldIsTheUniformTension) {
  const pd::MichellHole m = hole(0.3);
  const double nu = 0.3, E = 1, R = 1e4 * m.a;
  for (double t : {0.2, 1.3, 2.9, 4.1}) {
    const double x = m.x0 + R * std::cos(t), y = m.y0 + R * std::sin(t);
    const auto s = m.stress(x, y);
    EXPECT_NEAR(s[0], m.T, 1e-7 * m.T);
    EXPECT_NEAR(s[1], 0.0, 1e-7 * m.T);
    EXPECT_NEAR(s[2], 0.0, 1e-7 * m.T);
    // Plane strain under s_xx = T: e_xx = T (1 - nu^2)/E, e_yy = -T nu (1 + nu)/E; the
    // hole's terms fall as a/r, so relative to the uniform part they are ~1e-4 here.
    const auto u = m.displacement(x, y);
    EXPECT_NEAR(u[0] / (x - m.x0), m.T * (1 - nu * nu) / E, 1e-3 * m.T);
    EXPECT_NEAR(u[1] / (y - m.y0), -m.T * nu * (1 + nu) / E, 1e-3 * m.T);
  }
}

TEST(Michell, SceneFieldIsTheSameSolution) {
  const auto mat = pd::IsotropicElastic::from_E_nu(1.0, 0.3);
  const pd::AnalyticField f(
      pd::FieldSpec{"michell", {{"traction", 0.7}, {"radius", 0.2}, {"x0", 0.5}, {"y0", 0.4}}}, mat);
  const pd::MichellHole m = hole(0.3);
  const double p[2] = {0.9, 0.1};
  const auto u = f.displacement(p);
  const auto v = m.displacement(p[0], p[1]);
  EXPECT_NEAR(u[0], v[0], 1e-15);
  EXPECT_NEAR(u[1], v[1], 1e-15);
  EXPECT_FALSE(f.has_body_force());
  EXPECT_THROW(pd::AnalyticField(pd::FieldSpec{"michell", {{"traction", 1.0}}}, mat), std::invalid_argument);
}
