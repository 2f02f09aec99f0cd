// Bonds breaking between the load steps of an implicit (Newton) solve: a notched plate
// pulled apart through grips one horizon deep, free to slide sideways (a clamped edge, or
// a pull on the outer row alone, concentrates strain at the boundary and breaks bonds there). Bonds must break only ahead of the notch tip, where the strain
// concentrates, each load step must end converged on the final bond set, and a load
// below the critical one must break nothing.
#include <gtest/gtest.h>

#include <cmath>

#include "discretize/discretization.hpp"
#include "input/scene.hpp"
#include "run/simulation.hpp"

namespace {
const char* kNotchedPlate = R"(dimension: 2
domain:
  box: {min: [0, 0], max: [1, 1]}
  count: 30
horizon: {ratio: 3.0}
law: bond_based_constant_2d
influence: const
materials:
  - {E: 1, nu: 0.3333333333333333, plane: stress}
cracks:
  - segment: [[0.0, 0.5], [0.4, 0.5]]
boundary:
  - region: {box: {min: [0, 0], max: [1, 0.1]}}
    fixed: [y]
  - region: {box: {min: [0.9, 0], max: [1, 0.02]}}
    fixed: [x]
  - region: {box: {min: [0, 0.9], max: [1, 1]}}
    displacement: {y: PULL}
damage: {critical_stretch: 0.01}
solver: {load_steps: 4}
)";

struct PullResult {
  pd::RunSummary summary;
  pd::Bonds final_bonds, notch_cut;  // the bonds after the run; the bonds the notch alone cuts
  pd::Particles particles;
};

PullResult pull(double displacement) {
  std::string text = kNotchedPlate;
  text.replace(text.find("PULL"), 4, std::to_string(displacement));
  const pd::Scene scene = pd::parse_scene(text, "notched_plate.yaml");
  pd::Simulation sim(scene, [](const std::string&) {});
  PullResult r;
  r.summary = sim.run(false);
  r.final_bonds = sim.bonds();
  r.particles = sim.particles();
  r.notch_cut = pd::find_bonds(r.particles, scene.delta(), [](double, double) { return 1.0; });
  pd::cut_bonds(scene.cracks, r.particles, r.notch_cut);
  return r;
}
}  // namespace

TEST(ImplicitDamage, BondsBreakOnlyAheadOfTheNotchTip) {
  const PullResult r = pull(0.004);  // far-field strain 0.4%, below s0 = 1%: only the tip concentrates enough
  ASSERT_TRUE(r.summary.newton.converged) << r.summary.newton.message;
  ASSERT_GT(r.summary.newton.changes, 0) << "the load should break bonds at the notch tip";
  ASSERT_EQ(r.final_bonds.alpha.size(), r.notch_cut.alpha.size());
  const double delta = 3.0 / 30;
  int newly_broken = 0;
  for (int a = 0; a < r.particles.size(); ++a)
    for (int e = r.final_bonds.offsets[a]; e < r.final_bonds.offsets[a + 1]; ++e) {
      if (r.final_bonds.alpha[e] != 0.0 || r.notch_cut.alpha[e] == 0.0) continue;
      ++newly_broken;
      const int b = r.final_bonds.neighbor[e];
      const double mx = 0.5 * (r.particles.x[2 * a] + r.particles.x[2 * b]);
      const double my = 0.5 * (r.particles.x[2 * a + 1] + r.particles.x[2 * b + 1]);
      // Ahead of the tip (0.4, 0.5): within two horizons of it, not behind it, near the notch line.
      EXPECT_LT(std::hypot(mx - 0.4, my - 0.5), 2 * delta) << "bond " << a << "-" << b << " at (" << mx << ", " << my << ")";
      EXPECT_GT(mx, 0.4 - delta) << "bond " << a << "-" << b;
    }
  EXPECT_EQ(newly_broken, 2 * r.summary.newton.changes);  // both families' copies, counted once
  // The last solve of every step is on the final bond set and converged: the last record's
  // residual met the tolerance.
  const auto& last = r.summary.newton.history.back();
  EXPECT_LE(last.residual, 1e-9 * r.summary.newton.history.front().residual + 1e-300);
}

TEST(ImplicitDamage, ALoadBelowTheCriticalOneBreaksNothing) {
  const PullResult r = pull(0.001);
  ASSERT_TRUE(r.summary.newton.converged) << r.summary.newton.message;
  EXPECT_EQ(r.summary.newton.changes, 0);
  EXPECT_EQ(r.final_bonds.alpha, r.notch_cut.alpha);
  EXPECT_EQ(r.summary.text().find("bonds broken between load steps"), std::string::npos);
}
