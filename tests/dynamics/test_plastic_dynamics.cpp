// A law with memory in explicit dynamics (issue 29): the history is committed every time
// step, a pulse past yield leaves plastic extension where an elastic one leaves the history
// exactly at its initial value, and a run stopped and restarted from a checkpoint (which
// carries the history) ends bit for bit like the uninterrupted one. Dynamic relaxation, one
// load step, commits its converged answer once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "input/scene.hpp"
#include "relative_difference.hpp"
#include "run/dynamic_simulation.hpp"
#include "run/simulation.hpp"
#include "temp_files.hpp"

namespace {
// A plane-strain bar, 80 x 8 particles, released from a Gaussian stretch pulse of peak
// strain about 0.01 (E = 200: about 2 in stress, 8 times sigma_y = 0.25).
const char* kPulse = R"(dimension: 2
domain:
  box: {min: [0, 0], max: [2, 0.2]}
  spacing: 0.025
horizon: {ratio: 3.0}
law: elastic_plastic_plane_strain
materials: [{E: 200, nu: 0.3, density: 1, parameters: {sigma_y: 0.25}}]
boundary:
  - region: {all: true}
    fixed: [y]
dynamics:
  method: explicit
  steps: 120
  safety_factor: 0.8
  output_every: 10
  threads: 1
  initial:
    - region: {all: true}
      displacement: [1.0e-3, 0]
      gaussian: {axis: x, center: 1.0, width: 0.1}
)";

pd::Scene pulse(double sigma_y, const std::string& directory) {
  pd::Scene s = pd::parse_scene(kPulse, "pulse.yaml");
  s.materials[0].parameters["sigma_y"] = sigma_y;
  s.output.directory = pd::test::scratch_path("pd_plastic_dynamics_" + directory).string();
  return s;
}

double largest(const std::vector<double>& values) {
  double m = 0;
  for (double v : values) m = std::max(m, std::fabs(v));
  return m;
}
}  // namespace

TEST(PlasticDynamics, APulsePastYieldLeavesPlasticExtensionAnElasticOneNone) {
  pd::DynamicSimulation plastic(pulse(0.25, "plastic"), [](const std::string&) {});
  plastic.run(false);
  ASSERT_FALSE(plastic.bond_history().empty());
  EXPECT_GT(largest(plastic.bond_history()), 1e-5) << "the pulse yields the bar";

  pd::DynamicSimulation elastic(pulse(1e3, "elastic"), [](const std::string&) {});
  elastic.run(false);
  for (double h : elastic.bond_history()) ASSERT_EQ(h, 0.0);
  // Yielding changes the motion: the history is read by the forces, not only written.
  double apart = 0;
  for (std::size_t i = 0; i < plastic.displacement().size(); ++i)
    apart = std::max(apart, std::fabs(plastic.displacement()[i] - elastic.displacement()[i]));
  EXPECT_GT(apart, 1e-2 * largest(elastic.displacement()));
}

TEST(PlasticDynamics, ARestartFromACheckpointEndsBitForBitLikeTheUninterruptedRun) {
  pd::DynamicSimulation full(pulse(0.25, "full"), [](const std::string&) {});
  full.run(false);

  pd::Scene stopped = pulse(0.25, "parts");
  stopped.dynamics->checkpoint_every = 40;
  {
    pd::DynamicSimulation first(stopped, [](const std::string&) {});
    first.run(false, 90);  // stopped at step 90: the last checkpoint is step 80
  }
  pd::Scene resumed = stopped;
  resumed.dynamics->restart = stopped.output.directory + "/checkpoint.bin";
  pd::DynamicSimulation second(resumed, [](const std::string&) {});
  const pd::RunSummary b = second.run(false);
  EXPECT_EQ(b.dynamics->first_step, 80);
  ASSERT_GT(largest(full.bond_history()), 0.0);
  EXPECT_EQ(full.bond_history(), second.bond_history());  // bit for bit
  EXPECT_EQ(full.displacement(), second.displacement());
  EXPECT_EQ(full.velocity(), second.velocity());
}

// Mitchell's viscoelastic law under explicit dynamics: the driver gives the law its time
// step, so the back extension moves (a step of 0 would leave it 0 to the bit: beta = 0,
// decay = 1), and the Maxwell arm changes the motion against lambda_i = 0.
TEST(ViscoelasticDynamics, TheTimeStepReachesTheLawAndTheViscousArmActs) {
  auto scene = [](double lambda_i, const std::string& directory) {
    pd::Scene s = pulse(1.0, directory);
    s.law = "viscoelastic_plane_strain";
    s.materials[0].parameters = {{"lambda_i", lambda_i}, {"tau_b", 0.05}};
    return s;
  };
  pd::DynamicSimulation viscous(scene(0.5, "viscous"), [](const std::string&) {});
  viscous.run(false);
  const std::vector<double>& h = viscous.bond_history();  // back_extension, deviatoric_extension per bond
  ASSERT_FALSE(h.empty());
  double back = 0;
  for (std::size_t i = 0; i < h.size(); i += 2) back = std::max(back, std::fabs(h[i]));
  EXPECT_GT(back, 1e-6);
  pd::DynamicSimulation spring(scene(0.0, "spring"), [](const std::string&) {});
  spring.run(false);
  double apart = 0;
  for (std::size_t i = 0; i < viscous.displacement().size(); ++i)
    apart = std::max(apart, std::fabs(viscous.displacement()[i] - spring.displacement()[i]));
  EXPECT_GT(apart, 1e-2 * largest(spring.displacement()));
}

namespace {
// The static bar of tests/e2e/test_plastic_step.cpp, pulled past yield (a uniaxial strain
// of 2.5e-3 against a yield strain of about 1.3e-3), solved by relaxation or by Newton.
pd::Scene yielding_bar(bool relaxation) {
  std::string text = R"(dimension: 2
domain:
  box: {min: [0, 0], max: [4, 1]}
  count: 24
horizon: {ratio: 3.0}
law: elastic_plastic_plane_strain
materials: [{E: 200, nu: 0.3, density: 1, parameters: {sigma_y: 0.25}}]
boundary:
  - region: {side: left}
    fixed: [x, y]
  - region: {side: right}
    displacement: {x: 0.01}
solver: {tolerance: 1e-12, increment_tolerance: 0}
)";
  if (relaxation) text += "dynamics: {method: relaxation, steps: 200000, tolerance: 1.0e-11, threads: 1}\n";
  pd::Scene s = pd::parse_scene(text, "bar.yaml");
  s.output.directory =
      pd::test::scratch_path(relaxation ? "pd_plastic_relaxation" : "pd_plastic_newton").string();
  return s;
}

using pd::test::relative_difference;
}  // namespace

// Dynamic relaxation is one load step from the virgin body: its iterates read the initial
// history, as Newton's single step does, and the converged answer is committed once. So
// u and the committed plastic extension are Newton's to the relaxation tolerance; without
// the commit the history would stay 0.
TEST(PlasticRelaxation, ReachesNewtonsOneStepAnswerAndCommitsItsHistory) {
  pd::Simulation newton(yielding_bar(false), [](const std::string&) {});
  ASSERT_TRUE(newton.run(false).newton.converged);
  pd::DynamicSimulation relaxed(yielding_bar(true), [](const std::string&) {});
  const pd::RunSummary r = relaxed.run(false);
  ASSERT_TRUE(r.dynamics->converged);
  ASSERT_GT(largest(newton.bond_history()), 1e-4) << "the bar yields";
  EXPECT_LT(relative_difference(relaxed.displacement(), newton.displacement()), 1e-7);
  EXPECT_LT(relative_difference(relaxed.bond_history(), newton.bond_history()), 1e-6);
}
