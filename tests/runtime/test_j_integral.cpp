// The nonlocal J-integral (paper 004, runtime/post/j_integral.*) on the paper's edge-notched
// plate, coarse: zero without a notch, path independent with one, and the general
// (state-based) form against the paper's pairwise eq. (21).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <fmt/core.h>

#include "input/scene.hpp"
#include "post/j_integral.hpp"
#include "run/simulation.hpp"

namespace {
// Paper 004 Fig. 6 scaled to a unit plate: notch from the left edge to the centre along
// y = 1/2 (between two particle rows: count even), tension on top and bottom, a statically
// determinate support (u at the right-edge particle under the crack line, u_y at the
// left-edge one). Plane stress nu = 1/3; contours are boxes of half-width `halves` around
// the tip (0.5, 0.5).
std::string plate(const std::string& law, int count, bool notch, const std::vector<double>& halves) {
  const double h = 1.0 / count;
  std::string contours;
  for (double c : halves)
    contours += fmt::format("{}{{contour: {{min: [{}, {}], max: [{}, {}]}}}}", contours.empty() ? "" : ", ", 0.5 - c,
                            0.5 - c, 0.5 + c, 0.5 + c);
  return fmt::format(R"(dimension: 2
domain: {{box: {{min: [0, 0], max: [1, 1]}}, count: {}}}
horizon: {{ratio: 3.0}}
law: {}
influence: const
materials: [{{E: 1.0, nu: 0.3333333333333333, plane: stress}}]
{}
boundary:
  - {{region: {{side: top}}, traction: [0, 1.0e-3]}}
  - {{region: {{side: bottom}}, traction: [0, -1.0e-3]}}
  - {{region: {{box: {{min: [{}, {}], max: [1, 0.5]}}}}, fixed: [x, y]}}
  - {{region: {{box: {{min: [0, {}], max: [{}, 0.5]}}}}, fixed: [y]}}
output: {{j_integral: [{}]}}
)",
                     count, law, notch ? "cracks: [{segment: [[0, 0.5], [0.5, 0.5]]}]" : "", 1 - h, 0.5 - h, 0.5 - h, h,
                     contours);
}

std::vector<pd::JIntegralResult> run(const std::string& yaml) {
  pd::Simulation sim(pd::parse_scene(yaml, "plate.yaml"), [](const std::string&) {});
  return sim.run(false).j_integrals;
}
}  // namespace

// Paper 004 section 5: without a notch J vanishes (the paper reports 1e-15 Pa m).
TEST(JIntegral, UnnotchedPlateHasNoJ) {
  const double notched = run(plate("bond_based_conical_2d", 30, true, {0.3}))[0].J;
  const double plain = run(plate("bond_based_conical_2d", 30, false, {0.3}))[0].J;
  ASSERT_GT(notched, 0);
  EXPECT_LT(std::fabs(plain), 1e-9 * notched) << "J without a notch " << plain << ", with one " << notched;
}

// Path independence (paper 004 Table 5: about 2 % between contours away from the
// boundary) for the bond-based law, for which the general form is the paper's eq. (21).
TEST(JIntegral, BondBasedIsPathIndependentAndPairwise) {
  const auto j = run(plate("bond_based_conical_2d", 30, true, {0.2, 0.3}));
  ASSERT_EQ(j.size(), 2u);
  EXPECT_NEAR(j[0].J, j[1].J, 0.02 * j[1].J);
  for (const auto& r : j) EXPECT_NEAR(r.J, r.pairwise, 1e-12 * r.J);  // t_j<i> = -t_i<j> exactly
}

// A state-based law: the general form (t_i<j> and t_j<i> both from the families' own
// kernels) is path independent too. The pairwise eq. (21) with f = t_i<j> - t_j<i> differs
// from it by (1/2) sum V V (t_i<j> + t_j<i>) . (du_j - du_i)/dx1, second order in the
// smoothness of the field: small, but not zero.
TEST(JIntegral, StateBasedGeneralFormIsPathIndependent) {
  for (const char* law : {"silling_plane_strain", "lps_plane_strain"}) {
    const auto j = run(plate(law, 30, true, {0.2, 0.3}));
    EXPECT_NEAR(j[0].J, j[1].J, 0.02 * j[1].J) << law;
    for (const auto& r : j) {
      EXPECT_NE(r.J, r.pairwise) << law;
      EXPECT_NEAR(r.J, r.pairwise, 0.01 * r.J) << law;
    }
  }
}

TEST(JIntegral, ContourIsReportedOnTheLattice) {
  const auto j = run(plate("bond_based_conical_2d", 30, true, {0.3}));
  // h = 1/30: centres at (k + 1/2)/30; the box [0.2, 0.8] holds k = 6 .. 23, edges 0.2 and 0.8.
  EXPECT_NEAR(j[0].edge_min[0], 0.2, 1e-12);
  EXPECT_NEAR(j[0].edge_max[1], 0.8, 1e-12);
  EXPECT_EQ(j[0].inside, 18 * 18);
}
