// Crack pressure in time: a dynamic run scales it by its crack's time function, a
// static run by the load factor of the Newton load step.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "constraints/constraints.hpp"
#include "input/scene.hpp"
#include "run/dynamic_simulation.hpp"
#include "run/peridynamic_system.hpp"
#include "run/simulation.hpp"

namespace {
void quiet(const std::string&) {}

// A plate held on an outer collar with a pressurised crack in the middle (between two
// particle rows); the crack pressure is the only load.
const std::string kPlate = R"(dimension: 2
domain: {box: {min: [-1, -1], max: [1, 1]}, count: 30}
law: silling_plane_strain
materials: [{E: 1, nu: 0.25, density: 1}]
boundary:
  - region: {outside: {min: [-0.8, -0.8], max: [0.8, 0.8]}}
    fixed: [x, y]
)";

std::string crack(double pressure, const std::string& time_function = "") {
  std::string s =
      "cracks:\n  - segment: [[-0.3, 0], [0.3, 0]]\n    pressure: " + fmt::format("{:.17g}", pressure) + "\n";
  if (!time_function.empty()) s += "    time_function: " + time_function + "\n";
  return s;
}
const std::string kDynamics = "dynamics: {steps: 60, output_every: 10, progress_seconds: 0, threads: 1}\n";

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}
double max_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::fabs(a[i] - b[i]));
  return m;
}
}  // namespace

TEST(CrackPressureInTime, ADynamicRunScalesItByTheTimeFunction) {
  // Half the pressure through {constant: 0.5} moves the body exactly as half the
  // pressure given directly (the pair forces are linear in p; rounding only).
  pd::DynamicSimulation scaled(
      pd::parse_scene(kPlate + crack(0.002, "{constant: 0.5}") + kDynamics, "a.yaml"), quiet);
  scaled.run(false);
  pd::DynamicSimulation half(pd::parse_scene(kPlate + crack(0.001) + kDynamics, "b.yaml"), quiet);
  half.run(false);
  pd::DynamicSimulation full(pd::parse_scene(kPlate + crack(0.002) + kDynamics, "c.yaml"), quiet);
  full.run(false);
  ASSERT_GT(max_abs(half.displacement()), 0.0);
  EXPECT_LT(max_diff(scaled.displacement(), half.displacement()), 1e-12 * max_abs(half.displacement()));
  EXPECT_GT(max_diff(scaled.displacement(), full.displacement()), 0.3 * max_abs(half.displacement()));

  // A pressure switched on at t1 (a table: 0 until t1, then 1 within one step): before
  // t1 the body moves bit for bit as an unloaded one (not exactly zero: the internal
  // forces at u = 0 carry rounding of |Y| - |xi|), after it it does not.
  const pd::Scene probe = pd::parse_scene(kPlate + crack(0.002) + kDynamics, "d.yaml");
  pd::DynamicSimulation timing(probe, quiet);
  const double dt = timing.run(false, 1).dynamics->dt;
  const double t1 = 20.5 * dt;
  const std::string table = fmt::format("{{table: [[0, 0], [{:.17g}, 0], [{:.17g}, 1]]}}", t1, t1 + 0.5 * dt);
  const pd::Scene late = pd::parse_scene(kPlate + crack(0.002, table) + kDynamics, "e.yaml");
  ASSERT_TRUE(late.cracks[0].time.has_value());
  const pd::Scene off = pd::parse_scene(kPlate + crack(0.002, "{constant: 0}") + kDynamics, "f.yaml");
  for (int steps : {20, 22}) {
    pd::DynamicSimulation loaded(late, quiet), unloaded(off, quiet);
    loaded.run(false, steps);
    unloaded.run(false, steps);
    ASSERT_LT(max_abs(unloaded.velocity()), 1e-12);
    if (steps == 20) {
      EXPECT_EQ(loaded.displacement(), unloaded.displacement());
      EXPECT_EQ(loaded.velocity(), unloaded.velocity());
    } else {
      EXPECT_GT(max_diff(loaded.velocity(), unloaded.velocity()), 1e-6);
    }
  }
}

TEST(CrackPressureInTime, AStaticRunScalesItByTheLoadFactor) {
  // Two Newton load steps: the converged solution of step 1 (load factor 1/2) is the
  // static solution at half the pressure.
  const pd::Scene s =
      pd::parse_scene(kPlate + crack(0.002) + "solver: {load_steps: 2, tolerance: 1e-12}\n", "s.yaml");
  pd::Simulation sim(s, quiet);
  const pd::DofMap dofs = pd::scene_constraints(s, sim.particles());
  const auto pressure = pd::make_crack_pressure(s, sim.particles(), sim.bonds());
  ASSERT_NE(pressure, nullptr);
  pd::PeridynamicSystem system(sim.assembler(), {pressure.get()});
  pd::NewtonSettings settings;
  settings.load_steps = 2;
  settings.relative_tolerance = 1e-12;
  Eigen::VectorXd first_step;
  settings.after_step = [&](int step, double load, const Eigen::VectorXd& u) -> long long {
    if (step == 1) {
      EXPECT_EQ(load, 0.5);
      first_step = u;
    }
    return 0;
  };
  Eigen::VectorXd u = Eigen::VectorXd::Zero(system.size());
  ASSERT_TRUE(pd::NewtonSolver(settings).solve(system, dofs, u).converged);

  pd::Scene half_scene = pd::parse_scene(kPlate + crack(0.001) + "solver: {tolerance: 1e-12}\n", "h.yaml");
  pd::Simulation half(half_scene, quiet);
  half.run(false);
  const std::vector<double> at_half(first_step.data(), first_step.data() + first_step.size());
  const double scale = max_abs(half.displacement());
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(max_diff(at_half, half.displacement()), 1e-8 * scale);
  // And the full pressure at the last step: twice as far, up to the geometric
  // nonlinearity (relative O(strain) = O(p / E) times the tip concentration: 1.7e-3 here).
  const std::vector<double> at_full(u.data(), u.data() + u.size());
  EXPECT_NEAR(max_abs(at_full) / scale, 2.0, 5e-3);
}
