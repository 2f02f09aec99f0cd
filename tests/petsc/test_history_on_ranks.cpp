// A law with memory on the PETSc backend (issue 29): the static driver commits the history
// after every load step on every rank, from the gathered displacement, and each rank's
// families read it. A plastic bar pulled past yield, pushed back through zero and returned
// (load_path 0 1 -1 0), and a viscoelastic bar ramped and held in physical time
// (solver.duration), give the serial answer over this run's ranks (1, 2 or 3): the
// displacement and every bond's committed history to 1e-10.
#include <gtest/gtest.h>

#include <string>

#include "input/scene.hpp"
#include "relative_difference.hpp"
#include "run/simulation.hpp"

namespace pd {
namespace {

using pd::test::relative_difference;

const char* kBar = R"(dimension: 2
domain:
  box: {min: [0, 0], max: [4, 1]}
  count: 16
horizon: {ratio: 3.0}
boundary:
  - region: {side: left}
    fixed: [x, y]
  - region: {side: right}
    displacement: {x: 0.01}
)";

struct Answer {
  std::vector<double> u, history;
};

Answer solve(const std::string& tail, Backend backend) {
  Scene scene = parse_scene(std::string(kBar) + tail, "bar.yaml");
  scene.solver.backend = backend;
  Simulation sim(std::move(scene), [](const std::string&) {});
  EXPECT_TRUE(sim.run(false).newton.converged);
  EXPECT_EQ(sim.solver_plan().backend, backend);
  return {sim.displacement(), sim.bond_history()};
}

void expect_serial_answer(const std::string& tail) {
  const Answer serial = solve(tail, Backend::serial), ranks = solve(tail, Backend::petsc);
  ASSERT_GT(relative_difference(serial.history, std::vector<double>(serial.history.size(), 0.0)), 0.0);
  EXPECT_LT(relative_difference(ranks.u, serial.u), 1e-10);
  EXPECT_LT(relative_difference(ranks.history, serial.history), 1e-10);
}

TEST(HistoryOnRanks, APlasticPathThatUnloadsAndReversesGivesTheSerialAnswer) {
  expect_serial_answer(
      "law: elastic_plastic_plane_strain\n"
      "materials: [{E: 200, nu: 0.3, parameters: {sigma_y: 0.25}}]\n"
      "solver: {load_steps: 3, load_path: [0, 1, -1, 0], tolerance: 1.0e-13, increment_tolerance: 0}\n");
}

TEST(HistoryOnRanks, AViscoelasticRampAndHoldGivesTheSerialAnswer) {
  expect_serial_answer(
      "law: viscoelastic_plane_strain\n"
      "materials: [{E: 200, nu: 0.3, parameters: {lambda_i: 0.6, tau_b: 1.0}}]\n"
      "solver: {load_steps: 4, load_path: [0, 1, 1, 1, 1], duration: 2.0, tolerance: 1.0e-11, "
      "increment_tolerance: 0}\n");
}

}  // namespace
}  // namespace pd
