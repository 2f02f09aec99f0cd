// The nonlocal J-integral (paper 004, runtime/post/j_integral.*) on the paper's edge-notched
// plate, coarse: zero without a notch, path independent with one, and the general
// (state-based) form against the paper's pairwise eq. (21).
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "input/scene.hpp"
#include "input/yaml_keys.hpp"
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
    contours += fmt::format("{}{{contour: {{min: [{}, {}], max: [{}, {}]}}}}", contours.empty() ? "" : ", ",
                            0.5 - c, 0.5 - c, 0.5 + c, 0.5 + c);
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
                     count, law, notch ? "cracks: [{segment: [[0, 0.5], [0.5, 0.5]]}]" : "", 1 - h, 0.5 - h,
                     0.5 - h, h, contours);
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

namespace {
// scenes/paper004_griffith.yaml on a box of 4 half-lengths (the collar carries the exact
// Westergaard field, so the box size only moves the collar), delta = 3h.
std::string griffith(const std::string& law, int count) {
  return fmt::format(R"(dimension: 2
domain: {{box: {{min: [-0.7, -0.7], max: [0.7, 0.7]}}, count: {}}}
horizon: {{ratio: 3.0}}
law: {}
influence: const
materials: [{{E: 60, nu: 0.25, plane: strain}}]
boundary:
  - {{region: {{collar: {{horizons: 1}}}}, field: {{solution: westergaard, pressure: 0.1, half_length: 0.35}}}}
cracks: [{{segment: [[-0.35, 0], [0.35, 0]], pressure: 0.1}}]
output: {{j_integral: [{{contour: {{min: [0.2, -0.15], max: [0.5, 0.15]}}}}, {{contour: {{min: [0.1, -0.3], max: [0.6, 0.3]}}}}]}}
)",
                     count, law);
}
}  // namespace

// The Griffith check: J of the pressurised crack tends to K_I^2 / E' = p^2 pi a (1 - nu^2) / E
// as delta -> 0. studies/paper004_griffith.py (docs/paper004.md) measured, bond-based conical
// at delta = 3h on the 2.8-wide box: -24.0 % at delta/a = 0.30, -18.8 % at 0.15, -14.9 % at
// 0.10. Here, on the 1.4-wide box at delta/a = 0.30 and 0.15 (one run): bond-based -27.7 % and
// -21.3 %, Silling -31.3 % and -24.0 %; the bounds are those with about 10 % margin, and each
// halving of delta must cut the error by at least 15 % (measured: 23 %). The crack-face
// pressure inside the contours enters through the load term; without it J would not be path
// independent.
TEST(JIntegral, PressurisedCrackTendsToGriffith) {
  const double exact = 0.1 * 0.1 * M_PI * 0.35 * (1 - 0.25 * 0.25) / 60;
  for (const char* law : {"bond_based_conical_2d", "silling_plane_strain"}) {
    double previous = 0;
    // Silling's convergence is the study's (docs/paper004.md); here its coarse point only.
    const bool pairwise = std::string(law) == "bond_based_conical_2d";
    for (const auto& [count, bound] : {std::pair{40, 0.35}, std::pair{80, 0.27}}) {
      if (!pairwise && count > 40) continue;
      const auto j = run(griffith(law, count));
      EXPECT_NEAR(j[0].J, j[1].J, 0.005 * j[1].J) << law << " count " << count;
      EXPECT_NE(j[0].load_term, 0.0);
      const double error = std::fabs(j[1].J - exact) / exact;
      EXPECT_LT(error, bound) << law << " count " << count << ": J " << j[1].J << " exact " << exact;
      if (previous > 0) {
        EXPECT_LT(error, 0.85 * previous) << law << ": no convergence from " << previous << " to " << error;
      }
      previous = error;
    }
  }
}

// Bad input: the message names the file, the line and the key.
TEST(JIntegral, InvertedContourIsASceneErrorWithItsLine) {
  std::string yaml = plate("bond_based_conical_2d", 10, true, {0.3});
  const auto at = yaml.find("output:");
  ASSERT_NE(at, std::string::npos);
  yaml = yaml.substr(0, at) + "output: {j_integral: [{contour: {min: [0.8, 0.2], max: [0.2, 0.8]}}]}\n";
  try {
    pd::parse_scene(yaml, "plate.yaml");
    FAIL() << "an inverted contour was accepted";
  } catch (const pd::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("plate.yaml:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("j_integral[0]"), std::string::npos) << e.what();
  }
}
