// Issue 33: sensitivities of a static solve to the material parameters. The closed-form chain
// from a material's (E, nu) to a law's parameters against central differences of
// law_parameters; then on three bodies -- a 2D plate in plane stress (Silling's law), a 2D
// plate with a pre-crack (LPS, whose pair parameters and the cut bonds both enter), a 3D cube
// (Silling's 3D law) -- the adjoint gradient of a least-squares misfit against the forward
// route (one solve per parameter) and against central differences of the whole solve (the
// scene rebuilt and solved again at p +- h); and the refusals where the derivation does
// not hold.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "input/scene.hpp"
#include "kernel_abi.hpp"
#include "material/elastic_constants.hpp"
#include "run/simulation.hpp"
#include "sensitivity/equilibrium_sensitivity.hpp"

namespace {
const char* kPlate = R"(dimension: 2
domain:
  box: {min: [0, 0], max: [2, 1]}
  count: 16
horizon: {ratio: 3.0}
law: silling_plane_strain
influence: cubic
materials: [{name: plate, E: 200, nu: 0.3, plane: stress}]
boundary:
  - region: {side: left}
    fixed: [x, y]
  - region: {side: right}
    traction: [0.1, 0.04]
solver: {tolerance: 1e-13, increment_tolerance: 0}
)";

const char* kCrackedPlate = R"(dimension: 2
domain:
  box: {min: [0, 0], max: [2, 1]}
  count: 16
horizon: {ratio: 3.0}
law: lps_plane_strain
materials: [{name: rock, E: 60, nu: 0.2, plane: strain}]
boundary:
  - region: {side: left}
    fixed: [x, y]
  - region: {side: right}
    traction: [0.05, 0.02]
cracks:
  - segment: [[1, 0.3], [1, 1.2]]
solver: {tolerance: 1e-13, increment_tolerance: 0}
)";

const char* kCube = R"(dimension: 3
domain:
  box: {min: [0, 0, 0], max: [1, 1, 1]}
  count: 6
  placement: node
horizon: {ratio: 2.0}
law: silling_3d
influence: cubic
materials: [{name: steel, E: 200, nu: 0.25}]
boundary:
  - region: {side: back}
    fixed: [z]
  - region: {box: {min: [0, 0, 0], max: [0, 1, 0]}}
    fixed: [x]
  - region: {box: {min: [0, 0, 0], max: [1, 0, 0]}}
    fixed: [y]
  - region: {side: front}
    traction: [0.02, 0, 0.1]
solver: {tolerance: 1e-13, increment_tolerance: 0}
)";

std::vector<double> solve(const pd::Scene& scene) {
  pd::Simulation sim(scene, [](const std::string&) {});
  const pd::RunSummary r = sim.run(false);
  EXPECT_TRUE(r.newton.converged) << r.newton.message;
  return sim.displacement();
}

// J(u) = 1/2 |u - m|^2 over every dof.
double misfit(const std::vector<double>& u, const std::vector<double>& m) {
  double J = 0;
  for (std::size_t i = 0; i < u.size(); ++i) J += 0.5 * (u[i] - m[i]) * (u[i] - m[i]);
  return J;
}

// The "measured" field: the same body solved at other parameter values.
std::vector<double> measured(const pd::Scene& scene, const std::vector<pd::SceneParameter>& params) {
  pd::Scene s = scene;
  for (const pd::SceneParameter& p : params) s = pd::with_parameter(s, p, 0.9 * pd::parameter_value(s, p));
  return solve(s);
}

void expect_gradient_matches(const char* yaml, const std::vector<std::string>& names) {
  const pd::Scene scene = pd::parse_scene(yaml, "sensitivity.yaml");
  std::vector<pd::SceneParameter> params;
  for (const std::string& n : names) params.push_back(pd::parse_scene_parameter(scene, n));
  const std::vector<double> m = measured(scene, params);
  pd::Simulation sim(scene, [](const std::string&) {});
  ASSERT_TRUE(sim.run(false).newton.converged);
  const std::vector<double>& u = sim.displacement();
  pd::EquilibriumSensitivity sens(sim.model(), scene, params, u);
  Eigen::VectorXd dJdu(static_cast<Eigen::Index>(u.size()));
  for (std::size_t i = 0; i < u.size(); ++i) dJdu[static_cast<Eigen::Index>(i)] = u[i] - m[i];
  const Eigen::VectorXd adjoint = sens.adjoint_gradient(dJdu);
  EXPECT_EQ(sens.solves(), 1);
  const Eigen::MatrixXd dudp = sens.displacement_sensitivity();
  const Eigen::VectorXd forward = dudp.transpose() * dJdu;
  for (std::size_t j = 0; j < params.size(); ++j) {
    const auto jj = static_cast<Eigen::Index>(j);
    EXPECT_NEAR(adjoint[jj], forward[jj], 1e-9 * std::fabs(forward[jj])) << params[j].label();
    const double p = pd::parameter_value(scene, params[j]), h = 1e-5 * std::fabs(p);
    const double fd = (misfit(solve(pd::with_parameter(scene, params[j], p + h)), m) -
                       misfit(solve(pd::with_parameter(scene, params[j], p - h)), m)) /
                      (2 * h);
    EXPECT_NE(fd, 0.0) << params[j].label();
    EXPECT_NEAR(adjoint[jj], fd, 1e-6 * std::fabs(fd)) << params[j].label();
  }
}
}  // namespace

TEST(LawParameterDerivative, MatchesCentralDifferencesOfTheMaterialMap) {
  for (const char* name : {"silling_plane_strain", "silling_3d", "lps_plane_strain", "bond_based_constant_2d",
                           "oterkus_plane_strain"}) {
    const pd::abi::LawDescriptor* law = pd::abi::find_law(name);
    ASSERT_NE(law, nullptr) << name;
    for (pd::PlaneAssumption plane : {pd::PlaneAssumption::Strain, pd::PlaneAssumption::Stress})
      for (const char* key : {"E", "nu"}) {
        const double E = 70, nu = 0.27, h = 1e-6;
        const std::vector<double> d =
            pd::law_parameter_derivative(*law, pd::IsotropicElastic::from_E_nu(E, nu), plane, {}, key);
        const bool is_E = std::string(key) == "E";
        const auto at = [&](double s) {
          return pd::law_parameters(
              *law, pd::IsotropicElastic::from_E_nu(E + (is_E ? s : 0), nu + (is_E ? 0 : s)), plane, {});
        };
        const std::vector<double> up = at(h), down = at(-h);
        for (int i = 0; i < law->n_params; ++i)
          EXPECT_NEAR(d[i], (up[i] - down[i]) / (2 * h), 1e-6 * (1 + std::fabs(d[i])))
              << name << " d " << law->param_names[i] << " / d " << key;
      }
  }
}

TEST(LawParameterDerivative, RefusesAKeyTheLawDoesNotRead) {
  const pd::abi::LawDescriptor* law = pd::abi::find_law("silling_plane_strain");
  const auto elastic = pd::IsotropicElastic::from_E_nu(70, 0.27);
  EXPECT_THROW(pd::law_parameter_derivative(*law, elastic, pd::PlaneAssumption::Strain, {}, "sigma_y"),
               std::invalid_argument);
  EXPECT_THROW(
      pd::law_parameter_derivative(*law, elastic, pd::PlaneAssumption::Strain, {{"sigma_y", 1.0}}, "sigma_y"),
      std::invalid_argument);
}

TEST(EquilibriumSensitivity, PlaneStressPlateAdjointEqualsForwardAndDifferences) {
  expect_gradient_matches(kPlate, {"E", "plate.nu"});
}

TEST(EquilibriumSensitivity, CrackedPlateAdjointEqualsForwardAndDifferences) {
  expect_gradient_matches(kCrackedPlate, {"E", "nu"});
}

TEST(EquilibriumSensitivity, CubeAdjointEqualsForwardAndDifferences) {
  expect_gradient_matches(kCube, {"E", "nu"});
}

TEST(EquilibriumSensitivity, RefusesWhatTheDerivationDoesNotCover) {
  const pd::Scene plate = pd::parse_scene(kPlate, "plate.yaml");
  EXPECT_THROW(pd::parse_scene_parameter(plate, "steel.E"), std::invalid_argument);
  {
    const pd::Scene damaged =
        pd::parse_scene(std::string(kPlate) + "damage: {critical_stretch: 0.5}\n", "damaged.yaml");
    pd::Simulation sim(damaged, [](const std::string&) {});
    sim.run(false);
    EXPECT_THROW(pd::EquilibriumSensitivity(sim.model(), damaged, {pd::parse_scene_parameter(damaged, "E")},
                                            sim.displacement()),
                 std::invalid_argument);
  }
  {
    std::string yaml = kPlate;
    yaml.replace(yaml.find("solver: {"), 9, "solver: {linear: matrix_free, ");
    const pd::Scene matrix_free = pd::parse_scene(yaml, "matrix_free.yaml");
    pd::Simulation sim(matrix_free, [](const std::string&) {});
    sim.run(false);
    EXPECT_THROW(
        pd::EquilibriumSensitivity(sim.model(), matrix_free, {pd::parse_scene_parameter(matrix_free, "E")},
                                   sim.displacement()),
        std::invalid_argument);
  }
  {
    std::string yaml = kPlate;
    yaml.replace(yaml.find("silling_plane_strain"), 20, "elastic_plastic_plane_strain");
    yaml.replace(yaml.find("plane: stress}"), 14, "plane: strain, parameters: {sigma_y: 1.0}}");
    const pd::Scene plastic = pd::parse_scene(yaml, "plastic.yaml");
    pd::Simulation sim(plastic, [](const std::string&) {});
    sim.run(false);
    EXPECT_THROW(pd::EquilibriumSensitivity(sim.model(), plastic, {pd::parse_scene_parameter(plastic, "E")},
                                            sim.displacement()),
                 std::invalid_argument);
  }
}
