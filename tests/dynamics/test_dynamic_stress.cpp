// The peridynamic stress in dynamic runs (probes[i].quantity: stress, output.stress): a
// plate whose collar two horizons deep is held on the affine field u = eps x, with the
// correspondence law (it reproduces an affine deformation gradient exactly, so the
// stress of every whole family is C : eps; the static case is StressOutput.*):
//   - adaptive dynamic relaxation from rest ends at the affine field, and the stress
//     probe there is C : eps to the relaxation's tolerance;
//   - an explicit run started on the affine field (initial gradient, zero velocity) stays
//     there, and the probe is C : eps after every step as at the start.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "input/scene.hpp"
#include "run/dynamic_simulation.hpp"
#include "temp_files.hpp"

namespace {
std::string plate(const std::string& out, const std::string& dynamics) {
  return fmt::format(R"(dimension: 2
domain: {{box: {{min: [0, 0], max: [1, 1]}}, count: 16}}
horizon: {{ratio: 3.0}}
law: correspondence_plane_strain
materials: [{{E: 1.0, nu: 0.25, density: 1.0}}]
boundary:
  - {{region: {{collar: {{horizons: 2}}}}, field: {{solution: affine, e11: 1.0e-4, e22: -0.3e-4, e12: 0.4e-4}}}}
probes:
  - {{name: syy, region: {{box: {{min: [0.4, 0.4], max: [0.6, 0.6]}}}}, quantity: stress, component: yy}}
  - {{name: sxy, region: {{box: {{min: [0.4, 0.4], max: [0.6, 0.6]}}}}, quantity: stress, component: xy}}
output: {{directory: {}, vtu: false, stress: true}}
dynamics: {}
)",
                     out, dynamics);
}
// Plane strain, E = 1, nu = 1/4: lambda = mu = 0.4.
constexpr double kLambda = 0.4, kMu = 0.4, kE11 = 1e-4, kE22 = -0.3e-4, kE12 = 0.4e-4;
constexpr double kSyy = kLambda * (kE11 + kE22) + 2 * kMu * kE22, kSxy = 2 * kMu * kE12;
}  // namespace

TEST(DynamicStress, RelaxationEndsOnHookesLaw) {
  const auto dir = pd::test::fresh_directory("pd_dynamic_stress_relaxation");
  pd::DynamicSimulation sim(
      pd::parse_scene(
          plate(dir.string(), "{method: relaxation, tolerance: 1.0e-10, steps: 100000, threads: 1}"),
          "plate.yaml"),
      [](const std::string&) {});
  const pd::RunSummary r = sim.run(true);
  ASSERT_TRUE(r.dynamics->converged);
  ASSERT_EQ(r.probes.size(), 2u);
  // The relaxation stops at a residual 1e-10 of the load: the stress within 1e-6 of its size.
  EXPECT_NEAR(r.probes[0].value, kSyy, 1e-6 * std::fabs(kSyy));
  EXPECT_NEAR(r.probes[1].value, kSxy, 1e-6 * std::fabs(kSxy));
  const std::string csv = pd::test::read_text(dir / "result.csv");
  EXPECT_NE(csv.substr(0, csv.find('\n')).find(",stress_yy"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(DynamicStress, ExplicitRunOnTheAffineFieldStaysOnHookesLaw) {
  const auto dir = pd::test::fresh_directory("pd_dynamic_stress_explicit");
  pd::DynamicSimulation sim(
      pd::parse_scene(plate(dir.string(),
                            "{steps: 20, threads: 1, progress_seconds: 0, initial: [{region: {all: true}, "
                            "gradient: [[1.0e-4, 0.4e-4], [0.4e-4, -0.3e-4]]}]}"),
                      "plate.yaml"),
      [](const std::string&) {});
  const pd::RunSummary r = sim.run(true);
  ASSERT_EQ(r.probes.size(), 2u);
  EXPECT_NEAR(r.probes[0].value, kSyy, 1e-12);
  EXPECT_NEAR(r.probes[1].value, kSxy, 1e-12);
  std::filesystem::remove_all(dir);
}
