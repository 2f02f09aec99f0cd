// The quadrature is part of a checkpoint's identity: the same grid, law and horizon with
// another domain.quadrature, with or without domain.compensation, or with Gauss points,
// gives every bond another volume, so a checkpoint of one is refused by the others.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "dynamics/checkpoint.hpp"
#include "input/scene.hpp"
#include "run/dynamic_simulation.hpp"
#include "temp_files.hpp"

namespace {
void quiet(const std::string&) {}

pd::Scene bar(const std::string& domain_extra, const std::string& name) {
  pd::Scene s = pd::parse_scene(R"(dimension: 2
domain: {box: {min: [0, 0], max: [1, 0.15]}, spacing: 0.05)" +
                                    domain_extra + R"(}
horizon: {ratio: 3.0}
law: silling_plane_strain
influence: const
materials: [{name: bar, E: 1.0, nu: 0.25, density: 1.0}]
boundary: [{region: {all: true}, fixed: [y]}]
dynamics:
  steps: 10
  checkpoint_every: 10
  progress_seconds: 0
  threads: 1
  initial: [{region: {all: true}, displacement: [1.0e-3, 0], gaussian: {axis: x, center: 0.5, width: 0.1}}]
)",
                                "bar.yaml");
  const auto dir = pd::test::scratch_path("pd_checkpoint_quadrature_" + name);
  s.output.directory = dir.string();
  return s;
}

std::string checkpoint_of(const pd::Scene& scene) {
  pd::DynamicSimulation sim(scene, quiet);
  sim.run(false);
  return scene.output.directory + "/checkpoint.bin";
}

std::string restart_error(pd::Scene scene, const std::string& path) {
  scene.dynamics->restart = path;
  scene.dynamics->steps = 20;
  try {
    pd::DynamicSimulation sim(scene, quiet);
    sim.run(false);
  } catch (const pd::CheckpointError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(CheckpointQuadrature, AnotherQuadratureCompensationOrGaussPointsIsRefused) {
  const std::string plain = checkpoint_of(bar("", "plain"));
  const std::string gauss = checkpoint_of(bar(", gauss_points: {per_axis: 2}", "gauss"));
  // Each resumes its own run.
  EXPECT_EQ(restart_error(bar("", "plain_again"), plain), "");
  EXPECT_EQ(restart_error(bar(", gauss_points: {per_axis: 2}", "gauss_again"), gauss), "");
  // Compensation changes only the factors, partial_exact against partial_linear neither the
  // particles nor (on this grid) every bond: the quadrature entry must differ all the same.
  for (const std::string& other :
       {std::string(", compensation: true"), std::string(", gauss_points: {per_axis: 2}"),
        std::string(", gauss_points: {per_axis: 2, support: 3.5}")}) {
    const std::string& path = other.find("support") != std::string::npos ? gauss : plain;
    const std::string message = restart_error(bar(other, "other"), path);
    EXPECT_NE(message.find("quadrature:"), std::string::npos) << other << ": " << message;
  }
  const std::string linear = checkpoint_of(bar(", quadrature: partial_linear", "linear"));
  const std::string message = restart_error(bar(", quadrature: partial_exact", "exact"), linear);
  EXPECT_NE(message.find("quadrature: checkpoint partial_linear, this run partial_exact"), std::string::npos)
      << message;
}
