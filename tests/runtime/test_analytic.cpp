// The analytic fields: the Westergaard crack opening and the constant-strain edge values.
#include <gtest/gtest.h>

#include <cmath>

#include "fields/analytic.hpp"

TEST(Analytic, WestergaardCrackOpening) {
  pd::FieldSpec spec{"westergaard", {{"pressure", 0.1}, {"half_length", 2.0}}};
  const auto m = pd::IsotropicElastic::from_E_nu(10.0, 0.3);
  const pd::AnalyticField f(spec, m);
  for (double x : {-1.9, -1.0, 0.0, 0.5, 1.5}) {
    const double up[2] = {x, 1e-12}, down[2] = {x, -1e-12};
    const double opening = f.displacement(up)[1] - f.displacement(down)[1];
    EXPECT_NEAR(opening, 4 * (1 - 0.09) * 0.1 * std::sqrt(4 - x * x) / 10.0, 1e-9) << x;
  }
  // Far field decays; symmetry: u_x odd in x, u_y odd in y.
  const double p[2] = {3.0, 1.0}, q[2] = {-3.0, 1.0}, r[2] = {3.0, -1.0};
  EXPECT_NEAR(f.displacement(p)[0], -f.displacement(q)[0], 1e-15);
  EXPECT_NEAR(f.displacement(p)[1], -f.displacement(r)[1], 1e-15);
}

TEST(Analytic, ConstantStrainFieldsAtTheLoadedEdge) {
  const auto m = pd::IsotropicElastic::from_E_nu(1000.0, 0.25);
  const double T = 1e-3, H = 10, nu = 0.25, E = 1000;
  const double top[2] = {5.0, H};
  auto u = [&](const char* name) {
    return pd::AnalyticField(pd::FieldSpec{name, {{"traction", T}}}, m).displacement(top);
  };
  EXPECT_NEAR(u("uniaxial")[1], T * H * (1 - nu - 2 * nu * nu) / (E * (1 - nu)), 1e-15);
  EXPECT_NEAR(u("biaxial")[1], T * H * (1 - nu - 2 * nu * nu) / E, 1e-15);
  EXPECT_NEAR(u("shear")[0], 2 * T * H * (1 + nu) / E, 1e-15);
  EXPECT_THROW(pd::AnalyticField(pd::FieldSpec{"shear", {{"traction", T}, {"typo", 1}}}, m),
               std::invalid_argument);
}

TEST(Analytic, RotationMovesPointsRigidly) {
  const auto m = pd::IsotropicElastic::from_E_nu(1.0, 0.25);
  const pd::AnalyticField f(pd::FieldSpec{"rotation", {{"angle", 90.0}, {"x0", 1.0}}}, m);
  const double p[2] = {2.0, 0.0};  // (1, 0) from the centre goes to (0, 1)
  EXPECT_NEAR(f.displacement(p)[0], -1.0, 1e-15);
  EXPECT_NEAR(f.displacement(p)[1], 1.0, 1e-15);
  const pd::AnalyticField g(pd::FieldSpec{"rotation", {{"angle", 30.0}, {"stretch", 0.1}}}, m);
  const double q[2] = {0.3, -0.7};
  const auto u = g.displacement(q);
  EXPECT_NEAR(std::hypot(q[0] + u[0], q[1] + u[1]), 1.1 * std::hypot(q[0], q[1]), 1e-15);
}

TEST(Analytic, InclusionFieldSatisfiesTheInterfaceAndFarFieldConditions) {
  // Stresses from central differences of the field and plane-strain Hooke's law: the
  // radial traction is continuous at r = a and tends to T far away; u_r is continuous.
  const double E = 2.0, nu = 0.3, Ei = 50.0, nui = 0.2, T = 0.01, a = 0.4;
  const auto m = pd::IsotropicElastic::from_E_nu(E, nu), mi = pd::IsotropicElastic::from_E_nu(Ei, nui);
  const pd::AnalyticField f(
      pd::FieldSpec{"inclusion",
                    {{"traction", T}, {"radius", a}, {"E_inclusion", Ei}, {"nu_inclusion", nui}}},
      m);
  auto ur = [&](double r) {
    const double x[2] = {r * 0.6, r * 0.8};
    const auto u = f.displacement(x);
    return u[0] * 0.6 + u[1] * 0.8;
  };
  auto srr = [&](double r, const pd::IsotropicElastic& k) {
    const double e = 1e-6, err = (ur(r + e) - ur(r - e)) / (2 * e), ett = ur(r) / r;
    return k.lambda * (err + ett) + 2 * k.G * err;
  };
  EXPECT_NEAR(ur(a * (1 - 1e-12)), ur(a * (1 + 1e-12)), 1e-12);
  // Each side's traction extrapolated quadratically to r = a from 1, 2 and 3e-3 away.
  auto at_interface = [&](double side, const pd::IsotropicElastic& k) {
    return 3 * srr(a + side * 1e-3, k) - 3 * srr(a + side * 2e-3, k) + srr(a + side * 3e-3, k);
  };
  EXPECT_NEAR(at_interface(-1, mi), at_interface(1, m), 1e-8);
  EXPECT_NEAR(srr(1e3, m), T, 1e-7);
  // Equal materials: the uniform biaxial field, u_r = T r / (2 (lambda + mu)).
  const pd::AnalyticField same(
      pd::FieldSpec{"inclusion", {{"traction", T}, {"radius", a}, {"E_inclusion", E}, {"nu_inclusion", nu}}},
      m);
  const double x[2] = {0.1, 0.2};
  EXPECT_NEAR(same.displacement(x)[1], T * 0.2 / (2 * (m.lambda + m.G)), 1e-15);
}
