// Critical-stretch damage between the load steps of an implicit (Newton) solve, on the
// edge-notched plate of scenes/notched_plate_static.yaml. The critical load is found
// here, from an undamaged solve and the test's own bond-stretch loop, not from the
// code under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "input/scene.hpp"
#include "run/simulation.hpp"

namespace {
std::string scene_path(const char* name) { return std::string(PD_SOURCE_DIR) + "/scenes/" + name; }
void quiet(const std::string&) {}

const double kTip[2] = {0.5, 0.5};  // the notch runs from x = 0 to the tip along y = 0.5

// The stretch (|Y| - |xi|) / |xi| of bond e of particle a at displacement u.
double stretch(const pd::Particles& P, const pd::Bonds& B, const std::vector<double>& u, int a, int e) {
  const int b = B.neighbor[e], d = P.dim;
  double l2 = 0, r2 = 0;
  for (int c = 0; c < d; ++c) {
    const double xi = P.x[b * d + c] - P.x[a * d + c];
    const double y = xi + u[b * d + c] - u[a * d + c];
    l2 += y * y, r2 += xi * xi;
  }
  return (std::sqrt(l2) - std::sqrt(r2)) / std::sqrt(r2);
}

// The largest stretch over the intact bonds.
double largest_stretch(const pd::Simulation& sim) {
  const auto& P = sim.particles();
  const auto& B = sim.bonds();
  double s = -1;
  for (int a = 0; a < P.size(); ++a)
    for (int e = B.offsets[a]; e < B.offsets[a + 1]; ++e)
      if (B.alpha[e] != 0.0) s = std::max(s, stretch(P, B, sim.displacement(), a, e));
  return s;
}

// The scene with the top grip's pull scaled by `factor`, and without damage if asked.
pd::Scene plate(double factor, bool damage) {
  pd::Scene s = pd::read_scene(scene_path("notched_plate_static.yaml"));
  for (auto& bc : s.boundary)
    if (bc.kind == pd::BoundaryCondition::Kind::Displacement) bc.values[1] *= factor;
  if (!damage) s.damage.reset();
  return s;
}

// The out-of-balance force on the particles between the grips (they carry no load),
// relative to the largest internal force on the grips: an equilibrium check on the
// final bond set that does not trust the solver's own residual.
double free_imbalance(const pd::Simulation& sim) {
  const auto& P = sim.particles();
  std::vector<double> f(sim.displacement().size());
  sim.assembler().internal_forces(sim.displacement().data(), f.data());
  double inner = 0, grip = 0;
  for (int p = 0; p < P.size(); ++p) {
    const double y = P.position(p)[1];
    const double m = std::hypot(f[2 * p], f[2 * p + 1]);
    if (y > 0.1 && y < 0.9)
      inner = std::max(inner, m);
    else
      grip = std::max(grip, m);
  }
  return inner / grip;
}
}  // namespace

TEST(ImplicitDamage, BelowTheCriticalLoadNothingBreaks) {
  const double s0 = plate(1, true).damage->critical_stretch;
  pd::Simulation undamaged(plate(1, false), quiet);
  ASSERT_TRUE(undamaged.run(false).newton.converged);
  // Small strains: the largest stretch is proportional to the pull, so this factor
  // brings it to s0 (geometric nonlinearity is O(strain) = 1%, inside the 5% margin).
  const double critical = s0 / largest_stretch(undamaged);
  ASSERT_GT(critical, 0.5);
  ASSERT_LT(critical, 1.0) << "the scene's pull should lie above the critical one";

  pd::Simulation below(plate(0.95 * critical, true), quiet);
  const pd::RunSummary r = below.run(false);
  ASSERT_TRUE(r.newton.converged);
  ASSERT_TRUE(r.bonds_broken_by_damage.has_value());
  EXPECT_EQ(*r.bonds_broken_by_damage, 0);
  EXPECT_EQ(r.newton.resolves, 0);
  EXPECT_LT(largest_stretch(below), s0);
  // Same answer as the undamaged solve at the same pull (the damaged kernel variant
  // reads alpha = 1 where the intact one folds it: rounding only).
  pd::Simulation reference(plate(0.95 * critical, false), quiet);
  reference.run(false);
  double diff = 0, scale = 0;
  for (std::size_t i = 0; i < below.displacement().size(); ++i) {
    diff = std::max(diff, std::fabs(below.displacement()[i] - reference.displacement()[i]));
    scale = std::max(scale, std::fabs(reference.displacement()[i]));
  }
  EXPECT_LT(diff, 1e-12 * scale);
}

TEST(ImplicitDamage, AboveItBondsBreakOnlyAheadOfTheNotchTipAndStepsStayConverged) {
  const pd::Scene s = plate(1, true);
  const double s0 = s.damage->critical_stretch, delta = s.delta();
  std::vector<std::string> log;
  pd::Simulation sim(s, [&](const std::string& line) { log.push_back(line); });
  const std::vector<double> cut = sim.bonds().alpha;  // the notch only: nothing solved yet
  const pd::RunSummary r = sim.run(false);
  ASSERT_TRUE(r.newton.converged) << r.newton.message;
  ASSERT_TRUE(r.bonds_broken_by_damage.has_value());
  EXPECT_GT(*r.bonds_broken_by_damage, 0);
  EXPECT_GT(r.newton.resolves, 0);

  // Every newly broken bond lies at the tip or ahead of it, near the notch line, and
  // was in tension.
  const auto& P = sim.particles();
  const auto& B = sim.bonds();
  long long fresh = 0;
  for (int a = 0; a < P.size(); ++a)
    for (int e = B.offsets[a]; e < B.offsets[a + 1]; ++e) {
      if (cut[e] == 0.0 || B.alpha[e] != 0.0) continue;
      ++fresh;
      const double* xa = P.position(a);
      const double* xb = P.position(B.neighbor[e]);
      const double mx = 0.5 * (xa[0] + xb[0]), my = 0.5 * (xa[1] + xb[1]);
      EXPECT_GT(mx, kTip[0] - 0.5 * delta) << "behind the tip: " << mx << ", " << my;
      EXPECT_LT(std::hypot(mx - kTip[0], my - kTip[1]), 2 * delta)
          << "far from the tip: " << mx << ", " << my;
      EXPECT_GT(stretch(P, B, sim.displacement(), a, e), s0);
    }
  EXPECT_EQ(fresh, 2 * *r.bonds_broken_by_damage);  // both families' copies
  // Breaking ran to completion: no intact bond is left over the limit, and the final
  // bond set is in equilibrium.
  EXPECT_LE(largest_stretch(sim), s0);
  EXPECT_LT(free_imbalance(sim), 1e-9);
  // Every round converged, and each re-solve logged one line.
  int rounds_logged = 0;
  for (const auto& line : log) rounds_logged += line.find("bonds broke") != std::string::npos;
  EXPECT_EQ(rounds_logged, r.newton.resolves);
  std::vector<int> rounds(s.solver.load_steps + 1, 0);
  for (const auto& rec : r.newton.history) rounds[rec.step] = std::max(rounds[rec.step], rec.round);
  int total = 0;
  for (int n : rounds) total += n;
  EXPECT_EQ(total, r.newton.resolves);
  // The summary says what happened.
  EXPECT_NE(r.text().find("bonds broken between load steps"), std::string::npos);
  EXPECT_NE(r.json().find("\"resolves\""), std::string::npos);
  EXPECT_EQ(r.variant, "damaged (reads alpha)");
}

TEST(ImplicitDamage, TooFewReSolvesFailWithAMessage) {
  pd::Scene s = plate(1, true);
  s.damage->max_resolves = 1;
  pd::Simulation sim(s, quiet);
  try {
    sim.run(false);
    FAIL() << "expected the re-solve cap to stop the run";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("after 1 re-solves"), std::string::npos) << e.what();
  }
}
