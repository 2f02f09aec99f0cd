// The peridynamic stress as a run output (output.stress, probes[i].quantity: stress) and
// the affine analytic field, end to end through `pd run`'s driver: a plate whose collar
// two horizons deep is held on u = eps x. Every free particle then sees only whole families
// (its neighbours are a horizon or more from the edge), so the affine field is the discrete
// equilibrium (with one horizon, the truncated shape tensors of the collar unbalance the
// free particles next to it, and the stress inside is off by 39 % in
// sigma_yy, 3.6 % in sigma_xy); the correspondence law
// reproduces an affine deformation gradient exactly, so the interior stress is C : eps.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "input/scene.hpp"
#include "input/yaml_keys.hpp"
#include "run/simulation.hpp"
#include "temp_files.hpp"

namespace {
std::string plate(const std::string& out, const std::string& law, const std::string& extra) {
  return fmt::format(R"(dimension: 2
domain: {{box: {{min: [0, 0], max: [1, 1]}}, count: 20{}}}
horizon: {{ratio: 3.0}}
law: {}
materials: [{{E: 1.0, nu: 0.25}}]
boundary:
  - {{region: {{collar: {{horizons: 2}}}}, field: {{solution: affine, e11: 1.0e-4, e22: -0.3e-4, e12: 0.4e-4}}}}
probes:
  - {{name: syy, region: {{box: {{min: [0.4, 0.4], max: [0.6, 0.6]}}}}, quantity: stress, component: yy}}
  - {{name: sxy, region: {{box: {{min: [0.4, 0.4], max: [0.6, 0.6]}}}}, quantity: stress, component: xy}}
  - {{name: uy, region: {{box: {{min: [0.4, 0.4], max: [0.6, 0.6]}}}}, component: y}}
output: {{directory: {}, vtu: false, stress: true}}
)",
                     extra, law, out);
}
}  // namespace

TEST(StressOutput, ProbesAndFieldGiveHookesLawForAnAffineField) {
  const auto dir = pd::test::fresh_directory("pd_stress_output");
  pd::Simulation sim(pd::parse_scene(plate(dir.string(), "correspondence_plane_strain", ""), "plate.yaml"),
                     [](const std::string&) {});
  const pd::RunSummary r = sim.run(true);
  ASSERT_EQ(r.probes.size(), 3u);
  // Plane strain, E = 1, nu = 1/4: lambda = mu = 0.4.
  const double lambda = 0.4, mu = 0.4, e11 = 1e-4, e22 = -0.3e-4, e12 = 0.4e-4;
  EXPECT_NEAR(r.probes[0].value, lambda * (e11 + e22) + 2 * mu * e22, 1e-12);
  EXPECT_NEAR(r.probes[1].value, 2 * mu * e12, 1e-12);
  EXPECT_NEAR(r.probes[2].value, e12 * 0.5 + e22 * 0.5, 1e-12);  // mean of u_y = e12 x + e22 y over the box
  const std::string csv = pd::test::read_text(dir / "result.csv");
  const std::string header = csv.substr(0, csv.find('\n'));
  for (const char* column : {",stress_xx", ",stress_xy", ",stress_yx", ",stress_yy"})
    EXPECT_NE(header.find(column), std::string::npos) << column << " in " << header;
  std::filesystem::remove_all(dir);
}

TEST(StressOutput, SceneErrorsNameTheKey) {
  auto error_of = [](const std::string& yaml) {
    try {
      pd::parse_scene(yaml, "s.yaml");
    } catch (const pd::SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string good = plate("out", "silling_plane_strain", "");
  auto with = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  EXPECT_NE(error_of(with("component: yy", "component: y")).find("two letters"), std::string::npos);
  EXPECT_NE(error_of(with("component: yy", "component: zy")).find("not a component of a 2D scene"),
            std::string::npos);
  EXPECT_NE(error_of(with("quantity: stress, component: yy",
                          "quantity: stress, component: yy, reference: {solution: "
                          "uniaxial, traction: 1}"))
                .find("a stress probe has no reference"),
            std::string::npos);
  EXPECT_NE(error_of(with("e12: 0.4e-4", "e13: 0.4e-4")).find("e13 belongs to 3D scenes"), std::string::npos);
  EXPECT_NE(error_of(plate("out", "oterkus_plane_strain", ", compensation: true")).find("no energy kernel"),
            std::string::npos);
  EXPECT_NE(
      error_of(plate("out", "silling_plane_strain", ", compensation: true, perturbation: {amplitude: 0.1}"))
          .find("perturbed"),
      std::string::npos);
  EXPECT_EQ(error_of(plate("out", "silling_plane_strain", ", compensation: true")), "");
}
