// Static scenes solved by the PETSc backend on this run's ranks give the serial
// backend's displacement: the crack (crack pressure, Westergaard collar), uniaxial
// compression (tractions, rollers) and a 3D cube in tension.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "input/scene.hpp"
#include "run/simulation.hpp"

namespace pd {
namespace {

std::string scene_text(const std::string& name, const std::string& from, const std::string& to) {
  std::ifstream in(std::string(PD_SOURCE_DIR) + "/scenes/" + name);
  std::ostringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << name << ": " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::vector<double> solve(std::string text, bool petsc) {
  Scene scene = parse_scene(text, "scene.yaml");
  if (petsc) scene.solver.backend = Backend::petsc;
  Simulation sim(std::move(scene), [](const std::string&) {});
  sim.run(false);
  EXPECT_EQ(sim.solver_plan().backend, petsc ? Backend::petsc : Backend::serial);
  return sim.displacement();
}

void expect_same_displacement(const std::string& text) {
  const std::vector<double> serial = solve(text, false), distributed = solve(text, true);
  ASSERT_EQ(serial.size(), distributed.size());
  double diff = 0, norm = 0;
  for (std::size_t i = 0; i < serial.size(); ++i)
    diff += std::pow(serial[i] - distributed[i], 2), norm += serial[i] * serial[i];
  ASSERT_GT(norm, 0);
  EXPECT_LT(std::sqrt(diff / norm), 1e-8);
}

TEST(DistributedSolve, CrackEqualsSerial) {
  expect_same_displacement(scene_text("crack.yaml", "count: 80", "count: 24"));
}
TEST(DistributedSolve, UniaxialEqualsSerial) {
  expect_same_displacement(scene_text("uniaxial.yaml", "count: 20", "count: 14"));
}
TEST(DistributedSolve, CubeInTension3DEqualsSerial) {
  expect_same_displacement(scene_text("cube_tension.yaml", "count: 8", "count: 6"));
}

}  // namespace
}  // namespace pd
