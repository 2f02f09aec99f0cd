// Bad values in the dynamics, damage and time-function keys stop with file:line: key.
#include <gtest/gtest.h>

#include "input/scene.hpp"
#include "input/yaml_keys.hpp"

namespace {
const std::string kBase = R"(dimension: 2
domain: {box: {min: [0, 0], max: [1, 1]}, count: 4}
law: silling_plane_strain
materials: [{E: 1, nu: 0.25}]
)";

std::string error_of(const std::string& extra) {
  try {
    pd::parse_scene(kBase + extra, "s.yaml");
  } catch (const pd::SceneError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(DynamicsScene, BadValuesNameFileLineAndKey) {
  EXPECT_NE(error_of("dynamics: {method: explicit}\n").find("s.yaml:5: dynamics: steps"), std::string::npos)
      << error_of("dynamics: {method: explicit}\n");
  EXPECT_NE(error_of("dynamics: {steps: 10, safety_factor: 1.5}\n").find("s.yaml:5: dynamics.safety_factor"),
            std::string::npos);
  EXPECT_NE(error_of("dynamics: {steps: 10, dt: -1}\n").find("dynamics.dt"), std::string::npos);
  EXPECT_NE(error_of("dynamics: {steps: 10, wobble: 1}\n").find("unknown key 'wobble'"), std::string::npos);
  EXPECT_NE(error_of("dynamics: {method: implicit, steps: 1}\n").find("dynamics.method"), std::string::npos);
  EXPECT_NE(error_of("dynamics: {method: relaxation, dt: 1}\n").find("dynamics.dt"), std::string::npos);
  EXPECT_NE(error_of("dynamics: {steps: 1}\ndamage: {critical_stretch: -1}\n")
                .find("s.yaml:6: damage.critical_stretch"),
            std::string::npos);
  EXPECT_NE(error_of("dynamics: {steps: 1}\ndamage: {critical_stretch: 0.1, fracture_energy: 1}\n")
                .find("exactly one"),
            std::string::npos);
  // Damage without dynamics breaks bonds between Newton load steps; max_resolves is theirs.
  EXPECT_EQ(error_of("damage: {critical_stretch: 0.1, max_resolves: 3}\n"), "");
  EXPECT_NE(
      error_of("damage: {critical_stretch: 0.1, max_resolves: 0}\n").find("s.yaml:5: damage.max_resolves"),
      std::string::npos);
  EXPECT_NE(error_of("dynamics: {steps: 1}\ndamage: {critical_stretch: 0.1, max_resolves: 3}\n")
                .find("s.yaml:6: damage.max_resolves: max_resolves belongs to implicit"),
            std::string::npos);
  // A crack pressure's time function: dynamic scenes only, and only with a pressure.
  const std::string crack =
      "cracks:\n  - segment: [[0, 0.5], [0.5, 0.5]]\n    pressure: 1\n    time_function: {ramp: 1}\n";
  EXPECT_NE(error_of(crack).find("s.yaml:8: cracks[0].time_function: time functions need a dynamics section"),
            std::string::npos)
      << error_of(crack);
  EXPECT_EQ(error_of(crack + "dynamics: {steps: 1}\n"), "");
  EXPECT_NE(error_of(crack + "dynamics: {method: relaxation}\n").find("cracks[0].time_function: relaxation"),
            std::string::npos);
  const std::string no_pressure =
      "cracks:\n  - segment: [[0, 0.5], [0.5, 0.5]]\n    time_function: {ramp: 1}\n";
  EXPECT_NE(error_of(no_pressure + "dynamics: {steps: 1}\n")
                .find("s.yaml:7: cracks[0].time_function: a time function scales the crack pressure"),
            std::string::npos)
      << error_of(no_pressure + "dynamics: {steps: 1}\n");
  const std::string tf =
      "boundary:\n  - region: {side: top}\n    traction: [0, 1]\n    time_function: {ramp: 0}\n";
  EXPECT_NE(error_of(tf + "dynamics: {steps: 1}\n").find("s.yaml:8: boundary[0].time_function.ramp"),
            std::string::npos)
      << error_of(tf + "dynamics: {steps: 1}\n");
  const std::string table =
      "boundary:\n  - region: {side: top}\n    traction: [0, 1]\n    time_function: {table: [[0, 0], [0, "
      "1]]}\n";
  EXPECT_NE(error_of(table + "dynamics: {steps: 1}\n").find("increase strictly"), std::string::npos);
  const std::string ok_tf =
      "boundary:\n  - region: {side: top}\n    traction: [0, 1]\n    time_function: {sine: {period: 1}}\n";
  EXPECT_NE(error_of(ok_tf).find("time functions need a dynamics section"), std::string::npos);
  const std::string vel = "boundary:\n  - region: {side: top}\n    velocity: {y: 1}\n";
  EXPECT_NE(error_of(vel).find("velocity conditions need a dynamics section"), std::string::npos);
  EXPECT_EQ(error_of(vel + "dynamics: {steps: 1}\n"), "");
}

// dynamics.initial[i].gradient: a homogeneous-strain initial displacement u = H (x - origin)
// (paper 003 section 5.1's uniaxial strain), read as given; bad shapes name the key. (Its
// effect on a run: ctest paper003_dynamic_point, whose plate would not move without it.)
namespace {
std::string initial_error(const std::string& initial) {
  return error_of("dynamics:\n  steps: 1\n  initial:\n    - " + initial + "\n");
}
}  // namespace

TEST(InitialGradient, ReadAndBadShapesNamed) {
  EXPECT_EQ(initial_error("{gradient: [[1e-3, 0], [0, 0]], origin: [-0.5, 0]}"), "");
  const pd::Scene s = pd::parse_scene(
      kBase + "dynamics:\n  steps: 1\n  initial:\n    - {gradient: [[1, 2], [3, 4]], origin: [5, 6]}\n",
      "s.yaml");
  const pd::InitialCondition& ic = s.dynamics->initial.at(0);
  EXPECT_TRUE(ic.has_gradient);
  EXPECT_EQ(ic.gradient[0][1], 2);
  EXPECT_EQ(ic.gradient[1][0], 3);
  EXPECT_EQ(ic.origin[1], 6);
  EXPECT_NE(initial_error("{gradient: [[1, 0]]}")
                .find("s.yaml:8: dynamics.initial[0].gradient: expected 2 rows of 2 numbers"),
            std::string::npos)
      << initial_error("{gradient: [[1, 0]]}");
  EXPECT_NE(initial_error("{gradient: [[1, 0], [0]]}")
                .find("dynamics.initial[0].gradient[1]: expected 2 components"),
            std::string::npos)
      << initial_error("{gradient: [[1, 0], [0]]}");
  EXPECT_NE(initial_error("{gradient: [[1, 0], [0, .nan]]}").find("dynamics.initial[0].gradient[1]"),
            std::string::npos)
      << initial_error("{gradient: [[1, 0], [0, .nan]]}");
  EXPECT_NE(initial_error("{origin: [0, 0], displacement: [1, 0]}").find("origin belongs to a gradient"),
            std::string::npos);
  EXPECT_NE(initial_error("{region: {all: true}}").find("give displacement, velocity, gradient"),
            std::string::npos);
}
