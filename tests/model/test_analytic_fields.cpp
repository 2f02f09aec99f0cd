// The analytic fields satisfy their problems: stresses are computed here from the
// displacement by central differences and plane-strain Hooke's law, independently of
// the potentials the code uses, and checked against the boundary conditions
// (tractions, supports, crack-face pressure), equilibrium and the crack opening.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "fields/analytic.hpp"

namespace {

struct Stress {
  double xx, yy, xy;
};

// Plane strain: sigma = lambda tr(eps) I + 2 G eps with the 3D lambda and G.
Stress stress(const pd::AnalyticField& f, double E, double nu, double x, double y, double step) {
  auto u = [&](double px, double py) {
    const double p[2] = {px, py};
    return f.displacement(p);
  };
  const auto ux1 = u(x + step, y), ux0 = u(x - step, y), uy1 = u(x, y + step), uy0 = u(x, y - step);
  const double exx = (ux1[0] - ux0[0]) / (2 * step), eyy = (uy1[1] - uy0[1]) / (2 * step);
  const double exy = 0.5 * ((uy1[0] - uy0[0]) / (2 * step) + (ux1[1] - ux0[1]) / (2 * step));
  const double G = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  return {lambda * (exx + eyy) + 2 * G * exx, lambda * (exx + eyy) + 2 * G * eyy, 2 * G * exy};
}

pd::AnalyticField field(const std::string& name, std::map<std::string, double> params, double E, double nu) {
  return pd::AnalyticField(pd::FieldSpec{name, std::move(params)}, pd::IsotropicElastic::from_E_nu(E, nu));
}

}  // namespace

TEST(AnalyticFields, WestergaardCrackOpening) {
  for (double nu : {0.0, 0.25, 0.4}) {
    const double E = 60, p = 0.1, a = 0.35, x0 = 0.2, y0 = -0.1;
    const auto f = field("westergaard", {{"pressure", p}, {"half_length", a}, {"x0", x0}, {"y0", y0}}, E, nu);
    for (double s : {-0.99, -0.6, -0.2, 0.0, 0.3, 0.75, 0.97}) {
      const double x = x0 + s * a;
      const double up[2] = {x, y0 + 1e-13}, down[2] = {x, y0 - 1e-13};
      const double opening = f.displacement(up)[1] - f.displacement(down)[1];
      EXPECT_NEAR(opening, 4 * (1 - nu * nu) * p * std::sqrt(a * a - s * s * a * a) / E,
                  1e-9 * p * a / E * 1e3)
          << nu << " " << s;
      EXPECT_GT(opening, 0.0);  // the pressure opens the crack
    }
    // Ahead of the tips the line y = y0 does not open, and u_x is continuous across it.
    for (double s : {1.01, 1.5, -2.0}) {
      const double up[2] = {x0 + s * a, y0 + 1e-13}, down[2] = {x0 + s * a, y0 - 1e-13};
      EXPECT_NEAR(f.displacement(up)[1] - f.displacement(down)[1], 0.0, 1e-9 * p * a / E);
      EXPECT_NEAR(f.displacement(up)[0] - f.displacement(down)[0], 0.0, 1e-9 * p * a / E);
    }
  }
}

TEST(AnalyticFields, WestergaardTractionsEquilibriumAndFarField) {
  const double E = 10, nu = 0.3, p = 0.5, a = 1.0;
  const auto f = field("westergaard", {{"pressure", p}, {"half_length", a}}, E, nu);
  const double h = 1e-5;
  // Crack faces carry the pressure: sigma_yy = -p, sigma_xy = 0 just above and below.
  for (double x : {-0.8, -0.3, 0.1, 0.6}) {
    for (double y : {0.0005, -0.0005}) {
      const Stress s = stress(f, E, nu, x, y, 0.25 * std::fabs(y));
      EXPECT_NEAR(s.yy, -p, 3e-3 * p) << x << " " << y;
      EXPECT_NEAR(s.xy, 0.0, 3e-3 * p) << x << " " << y;
    }
  }
  // Equilibrium div sigma = 0 at random points away from the crack (nested differences).
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int k = 0; k < 20; ++k) {
    const double x = u(rng), y = u(rng);
    if (std::fabs(y) < 0.2 && std::fabs(x) < 1.2) continue;
    const double d = 1e-3;
    const Stress sx1 = stress(f, E, nu, x + d, y, h), sx0 = stress(f, E, nu, x - d, y, h);
    const Stress sy1 = stress(f, E, nu, x, y + d, h), sy0 = stress(f, E, nu, x, y - d, h);
    EXPECT_NEAR((sx1.xx - sx0.xx) / (2 * d) + (sy1.xy - sy0.xy) / (2 * d), 0.0, 1e-4 * p / a)
        << x << " " << y;
    EXPECT_NEAR((sx1.xy - sx0.xy) / (2 * d) + (sy1.yy - sy0.yy) / (2 * d), 0.0, 1e-4 * p / a)
        << x << " " << y;
  }
  // Stresses and displacements vanish far away (sigma ~ p a^2 / r^2).
  const Stress far = stress(f, E, nu, 60.0, 80.0, 1e-3);
  EXPECT_LT(std::fabs(far.xx) + std::fabs(far.yy) + std::fabs(far.xy), 1e-3 * p);
  const double pf[2] = {60.0, 80.0};
  EXPECT_LT(std::hypot(f.displacement(pf)[0], f.displacement(pf)[1]), 0.02 * p * a / E);
}

TEST(AnalyticFields, ConstantStrainFieldsSatisfyTheirBoundaryConditions) {
  const double E = 1000, T = -1e-3, H = 10, W = 10;
  for (double nu : {0.0, 0.25}) {
    const auto uni = field("uniaxial", {{"traction", T}}, E, nu);
    const auto bi = field("biaxial", {{"traction", T}}, E, nu);
    const auto sh = field("shear", {{"traction", T}}, E, nu);
    const double step = 1e-3;
    for (double s : {0.0, 0.3, 0.5, 1.0}) {
      // Uniaxial: clamped bottom, rollers on the sides (u_x = 0), traction T along y on top.
      const double bottom[2] = {s * W, 0.0}, left[2] = {0.0, s * H}, right[2] = {W, s * H};
      EXPECT_EQ(uni.displacement(bottom)[0], 0.0);
      EXPECT_EQ(uni.displacement(bottom)[1], 0.0);
      EXPECT_EQ(uni.displacement(left)[0], 0.0);
      EXPECT_EQ(uni.displacement(right)[0], 0.0);
      Stress st = stress(uni, E, nu, s * W, H, step);
      EXPECT_NEAR(st.yy, T, 1e-9);
      EXPECT_NEAR(st.xy, 0.0, 1e-12);
      // Biaxial: rollers on bottom (u_y = 0) and left (u_x = 0), normal traction T on top and right.
      EXPECT_EQ(bi.displacement(bottom)[1], 0.0);
      EXPECT_EQ(bi.displacement(left)[0], 0.0);
      st = stress(bi, E, nu, s * W, s * H, step);
      EXPECT_NEAR(st.xx, T, 1e-9);
      EXPECT_NEAR(st.yy, T, 1e-9);
      EXPECT_NEAR(st.xy, 0.0, 1e-12);
      // Simple shear: clamped bottom, horizontal rollers on the sides (u_y = 0), tangential T on top.
      EXPECT_EQ(sh.displacement(bottom)[0], 0.0);
      EXPECT_EQ(sh.displacement(bottom)[1], 0.0);
      EXPECT_EQ(sh.displacement(left)[1], 0.0);
      EXPECT_EQ(sh.displacement(right)[1], 0.0);
      st = stress(sh, E, nu, s * W, H, step);
      EXPECT_NEAR(st.xy, T, 1e-9);
      EXPECT_NEAR(st.yy, 0.0, 1e-9);
    }
  }
}

TEST(AnalyticFields, OriginShiftAndMaterialOverride) {
  // x0, y0 move the fixed corner; E and nu given in the field override the material's.
  const auto base = field("biaxial", {{"traction", 1e-3}, {"E", 200}, {"nu", 0.2}}, 1000, 0.0);
  const auto moved =
      field("biaxial", {{"traction", 1e-3}, {"E", 200}, {"nu", 0.2}, {"x0", 1}, {"y0", 2}}, 1000, 0.0);
  const double a[2] = {3.0, 4.0}, b[2] = {4.0, 6.0};
  EXPECT_DOUBLE_EQ(base.displacement(a)[0], moved.displacement(b)[0]);
  EXPECT_DOUBLE_EQ(base.displacement(a)[1], moved.displacement(b)[1]);
  const Stress s = stress(base, 200, 0.2, 3.0, 4.0, 1e-3);
  EXPECT_NEAR(s.yy, 1e-3, 1e-12);
}

TEST(AnalyticFields, BadParametersAreRejected) {
  EXPECT_THROW(field("westergaard", {{"pressure", 1}}, 1, 0.2), std::invalid_argument);
  EXPECT_THROW(field("shear", {}, 1, 0.2), std::invalid_argument);
  EXPECT_THROW(field("shear", {{"traction", 1}, {"typo", 1}}, 1, 0.2), std::invalid_argument);
  EXPECT_THROW(field("torsion", {{"traction", 1}}, 1, 0.2), std::invalid_argument);
}
