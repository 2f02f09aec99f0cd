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
  EXPECT_NE(error_of("dynamics: {method: explicit}\n").find("s.yaml:5: dynamics: steps"), std::string::npos) << error_of("dynamics: {method: explicit}\n");
  EXPECT_NE(error_of("dynamics: {steps: 10, safety_factor: 1.5}\n").find("s.yaml:5: dynamics.safety_factor"), std::string::npos);
  EXPECT_NE(error_of("dynamics: {steps: 10, dt: -1}\n").find("dynamics.dt"), std::string::npos);
  EXPECT_NE(error_of("dynamics: {steps: 10, wobble: 1}\n").find("unknown key 'wobble'"), std::string::npos);
  EXPECT_NE(error_of("dynamics: {method: implicit, steps: 1}\n").find("dynamics.method"), std::string::npos);
  EXPECT_NE(error_of("dynamics: {method: relaxation, dt: 1}\n").find("dynamics.dt"), std::string::npos);
  EXPECT_NE(error_of("dynamics: {steps: 1}\ndamage: {critical_stretch: -1}\n").find("s.yaml:6: damage.critical_stretch"), std::string::npos);
  EXPECT_NE(error_of("dynamics: {steps: 1}\ndamage: {critical_stretch: 0.1, fracture_energy: 1}\n").find("exactly one"), std::string::npos);
  // Damage without dynamics breaks bonds between Newton load steps; max_resolves is theirs.
  EXPECT_EQ(error_of("damage: {critical_stretch: 0.1, max_resolves: 3}\n"), "");
  EXPECT_NE(error_of("damage: {critical_stretch: 0.1, max_resolves: 0}\n").find("s.yaml:5: damage.max_resolves"), std::string::npos);
  EXPECT_NE(error_of("dynamics: {steps: 1}\ndamage: {critical_stretch: 0.1, max_resolves: 3}\n").find("s.yaml:6: damage.max_resolves: max_resolves belongs to implicit"),
            std::string::npos);
  // A crack pressure's time function: dynamic scenes only, and only with a pressure.
  const std::string crack = "cracks:\n  - segment: [[0, 0.5], [0.5, 0.5]]\n    pressure: 1\n    time_function: {ramp: 1}\n";
  EXPECT_NE(error_of(crack).find("s.yaml:8: cracks[0].time_function: time functions need a dynamics section"), std::string::npos)
      << error_of(crack);
  EXPECT_EQ(error_of(crack + "dynamics: {steps: 1}\n"), "");
  EXPECT_NE(error_of(crack + "dynamics: {method: relaxation}\n").find("cracks[0].time_function: relaxation"), std::string::npos);
  const std::string no_pressure = "cracks:\n  - segment: [[0, 0.5], [0.5, 0.5]]\n    time_function: {ramp: 1}\n";
  EXPECT_NE(error_of(no_pressure + "dynamics: {steps: 1}\n").find("s.yaml:7: cracks[0].time_function: a time function scales the crack pressure"),
            std::string::npos)
      << error_of(no_pressure + "dynamics: {steps: 1}\n");
  const std::string tf = "boundary:\n  - region: {side: top}\n    traction: [0, 1]\n    time_function: {ramp: 0}\n";
  EXPECT_NE(error_of(tf + "dynamics: {steps: 1}\n").find("s.yaml:8: boundary[0].time_function.ramp"), std::string::npos)
      << error_of(tf + "dynamics: {steps: 1}\n");
  const std::string table = "boundary:\n  - region: {side: top}\n    traction: [0, 1]\n    time_function: {table: [[0, 0], [0, 1]]}\n";
  EXPECT_NE(error_of(table + "dynamics: {steps: 1}\n").find("increase strictly"), std::string::npos);
  const std::string ok_tf = "boundary:\n  - region: {side: top}\n    traction: [0, 1]\n    time_function: {sine: {period: 1}}\n";
  EXPECT_NE(error_of(ok_tf).find("time functions need a dynamics section"), std::string::npos);
  const std::string vel = "boundary:\n  - region: {side: top}\n    velocity: {y: 1}\n";
  EXPECT_NE(error_of(vel).find("velocity conditions need a dynamics section"), std::string::npos);
  EXPECT_EQ(error_of(vel + "dynamics: {steps: 1}\n"), "");
}
