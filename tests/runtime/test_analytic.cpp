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
  auto u = [&](const char* name) { return pd::AnalyticField(pd::FieldSpec{name, {{"traction", T}}}, m).displacement(top); };
  EXPECT_NEAR(u("uniaxial")[1], T * H * (1 - nu - 2 * nu * nu) / (E * (1 - nu)), 1e-15);
  EXPECT_NEAR(u("biaxial")[1], T * H * (1 - nu - 2 * nu * nu) / E, 1e-15);
  EXPECT_NEAR(u("shear")[0], 2 * T * H * (1 + nu) / E, 1e-15);
  EXPECT_THROW(pd::AnalyticField(pd::FieldSpec{"shear", {{"traction", T}, {"typo", 1}}}, m), std::invalid_argument);
}
