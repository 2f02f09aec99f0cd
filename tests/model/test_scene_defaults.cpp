// A minimal scene gets the defaults that docs/scene_format.md documents, and the
// optional keys are read into the right fields.
#include <gtest/gtest.h>

#include "input/scene.hpp"

namespace {
const char* kMinimal = R"(domain:
  box: {min: [0, 0], max: [1, 1]}
  spacing: 0.1
law: silling_plane_strain
materials:
  - {E: 1, nu: 0.25}
)";
}  // namespace

TEST(SceneDefaults, MinimalSceneGetsTheDocumentedDefaults) {
  const pd::Scene s = pd::parse_scene(kMinimal, "m.yaml");
  EXPECT_EQ(s.file, "m.yaml");
  EXPECT_EQ(s.dim, 2);
  EXPECT_EQ(s.placement, pd::Placement::cell);
  EXPECT_EQ(s.perturbation, 0.0);
  EXPECT_EQ(s.seed, 1u);
  EXPECT_TRUE(s.holes.empty() && s.inclusions.empty());
  EXPECT_DOUBLE_EQ(s.delta(), 3.0 * 0.1);
  EXPECT_EQ(s.influence, "const");
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].name, "default");
  EXPECT_EQ(s.materials[0].plane, pd::PlaneAssumption::Strain);
  EXPECT_EQ(s.materials[0].density, 1.0);
  EXPECT_TRUE(s.boundary.empty() && s.cracks.empty() && s.probes.empty());
  EXPECT_FALSE(s.reference.has_value());
  EXPECT_EQ(s.solver.linear, pd::LinearMethod::automatic);
  EXPECT_EQ(s.solver.nonlinear, pd::NonlinearMethod::newton);
  EXPECT_EQ(s.solver.load_steps, 1);
  EXPECT_EQ(s.solver.tolerance, 1e-10);
  EXPECT_EQ(s.solver.max_iterations, 30);
  EXPECT_EQ(s.output.directory, "out");
  EXPECT_TRUE(s.output.vtu);
  EXPECT_TRUE(s.output.csv);
}

TEST(SceneDefaults, OptionalKeysAreRead) {
  const std::string text = std::string(kMinimal) + R"(horizon: {length: 0.25}
influence: cubic
solver: {nonlinear: newton, linear: cg, load_steps: 3, tolerance: 1.0e-8, max_iterations: 7}
output: {directory: elsewhere, vtu: false, csv: false}
cracks:
  - {segment: [[0.2, 0.5], [0.8, 0.5]], pressure: 2}
boundary:
  - {region: {side: top, thickness: 0.3}, field: {solution: westergaard, pressure: 2, half_length: 0.3, nu: 0.1}, components: [y]}
)";
  const pd::Scene s = pd::parse_scene(text, "o.yaml");
  EXPECT_DOUBLE_EQ(s.delta(), 0.25);
  EXPECT_EQ(s.influence, "cubic");
  EXPECT_EQ(s.solver.linear, pd::LinearMethod::cg);
  EXPECT_EQ(s.solver.load_steps, 3);
  EXPECT_EQ(s.solver.tolerance, 1e-8);
  EXPECT_EQ(s.solver.max_iterations, 7);
  EXPECT_EQ(s.output.directory, "elsewhere");
  EXPECT_FALSE(s.output.vtu || s.output.csv);
  ASSERT_EQ(s.cracks.size(), 1u);
  EXPECT_EQ(s.cracks[0].pressure, 2.0);
  EXPECT_EQ(s.cracks[0].points[1][0], 0.8);
  ASSERT_EQ(s.boundary.size(), 1u);
  const auto& bc = s.boundary[0];
  EXPECT_EQ(bc.kind, pd::BoundaryCondition::Kind::Field);
  EXPECT_EQ(bc.region.thickness, 0.3);
  EXPECT_FALSE(bc.components[0]);
  EXPECT_TRUE(bc.components[1]);
  EXPECT_EQ(bc.field.solution, "westergaard");
  EXPECT_EQ(bc.field.parameters.at("half_length"), 0.3);
  EXPECT_EQ(bc.field.parameters.at("nu"), 0.1);
  EXPECT_EQ(bc.field.parameters.count("E"), 0u);  // from the material, not invented
}
