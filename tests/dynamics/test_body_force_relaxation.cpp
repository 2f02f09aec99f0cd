// A dynamic run applies `body_force: {field: ...}` in full from t = 0: adaptive dynamic
// relaxation of the manufactured u2 scene ends where the static Newton solve does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "input/scene.hpp"
#include "run/dynamic_simulation.hpp"
#include "run/simulation.hpp"

namespace {
const std::string kScene = R"(dimension: 2
domain:
  box: {min: [0, 0], max: [1, 1]}
  count: 12
horizon: {ratio: 3.0}
law: lps_plane_strain
influence: const
materials:
  - {E: 1.25, nu: 0.25}
boundary:
  - region: {collar: {horizons: 1}}
    field: {solution: u2, amplitude: 0.001}
body_force: {field: {solution: u2, amplitude: 0.001}}
)";
}  // namespace

TEST(BodyForceRelaxation, RelaxationEndsAtTheStaticSolution) {
  pd::Simulation statics(pd::parse_scene(kScene, "u2.yaml"), [](const std::string&) {});
  ASSERT_TRUE(statics.run(false).newton.converged);
  const std::string relaxation =
      kScene + "dynamics: {method: relaxation, tolerance: 1.0e-10, steps: 100000}\n";
  pd::DynamicSimulation dynamic(pd::parse_scene(relaxation, "u2_relaxation.yaml"), [](const std::string&) {});
  const pd::RunSummary s = dynamic.run(false);
  ASSERT_TRUE(s.dynamics->converged);
  double largest = 0, difference = 0;
  for (std::size_t i = 0; i < statics.displacement().size(); ++i) {
    largest = std::max(largest, std::fabs(statics.displacement()[i]));
    difference = std::max(difference, std::fabs(statics.displacement()[i] - dynamic.displacement()[i]));
  }
  EXPECT_GT(largest, 9e-4);  // u2's amplitude: the body force and the layer did load the body
  EXPECT_LT(difference, 1e-8 * largest);
  bool listed = false;
  for (const std::string& e : s.effects) listed = listed || e.find("field u2") != std::string::npos;
  EXPECT_TRUE(listed);
}
