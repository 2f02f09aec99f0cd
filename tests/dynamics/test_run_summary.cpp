// The run summary and log of static and dynamic runs list only the effects the scene
// calls for (no array, no kernel variant, no log line for the others), and a dynamic
// run's time series carries the probes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "input/scene.hpp"
#include "run/dynamic_simulation.hpp"
#include "run/simulation.hpp"
#include "temp_files.hpp"

namespace {
std::string scene_path(const char* name) { return std::string(PD_SOURCE_DIR) + "/scenes/" + name; }

struct Captured {
  std::string log;
  pd::Simulation::Log sink() {
    return [this](const std::string& line) { log += line + "\n"; };
  }
};
}  // namespace

TEST(RunSummary, StaticSceneWithoutDamageHasNoDamageAnywhere) {
  Captured c;
  pd::Simulation sim(pd::read_scene(scene_path("uniaxial.yaml")), c.sink());
  const pd::RunSummary r = sim.run(false);
  EXPECT_EQ(sim.damage(), nullptr);
  EXPECT_TRUE(sim.assembler().intact());
  EXPECT_EQ(r.variant, "intact (alpha folded to 1)");
  EXPECT_FALSE(r.bonds_broken_by_damage.has_value());
  for (const char* absent :
       {"damage", "critical-stretch", "re-solve", "resolve", "inertia", "relaxation", "crack pressure"}) {
    EXPECT_EQ(c.log.find(absent), std::string::npos) << absent;
    EXPECT_EQ(r.text().find(absent), std::string::npos) << absent;
    EXPECT_EQ(r.json().find(absent), std::string::npos) << absent;
  }
  EXPECT_NE(r.text().find("elasticity"), std::string::npos);
}

TEST(RunSummary, StaticSceneWithDamageSaysSo) {
  Captured c;
  pd::Simulation sim(pd::read_scene(scene_path("notched_plate_static.yaml")), c.sink());
  // Set up but not solved: the damaged kernels and the damage object exist already.
  ASSERT_NE(sim.damage(), nullptr);
  EXPECT_FALSE(sim.assembler().intact());
  EXPECT_NE(c.log.find("effect: damage: critical-stretch bond breaking (PMB), s0 = 0.01, tension only, "
                       "between load steps"),
            std::string::npos)
      << c.log;
  EXPECT_EQ(c.log.find("inertia"), std::string::npos);
}

TEST(RunSummary, DynamicSceneLogListsOnlyItsEffects) {
  Captured c;
  pd::Scene wave = pd::read_scene(scene_path("wave_bar.yaml"));
  wave.dynamics->steps = 2;
  pd::DynamicSimulation sim(wave, c.sink());
  const pd::RunSummary r = sim.run(false);
  EXPECT_EQ(sim.damage(), nullptr);
  EXPECT_TRUE(sim.has_masses());
  for (const char* absent :
       {"damage", "critical-stretch", "crack", "damping", "external loads", "relaxation", "Newton"})
    EXPECT_EQ(c.log.find(absent), std::string::npos) << absent;
  EXPECT_NE(c.log.find("effect: inertia"), std::string::npos);
  EXPECT_NE(r.json().find("\"dt_stable_estimate\""), std::string::npos);
}

TEST(RunSummary, RelaxationTimeSeriesCarriesTheProbe) {
  pd::Scene s = pd::read_scene(scene_path("relaxation_uniaxial.yaml"));
  const auto dir = pd::test::scratch_path("pd_probe_series");
  s.output.directory = dir.string();
  s.dynamics->progress_seconds = 0;
  pd::DynamicSimulation sim(s, [](const std::string&) {});
  const pd::RunSummary r = sim.run(true);
  // The probe's mean over its region, computed here from the particles.
  const auto& P = sim.particles();
  double sum = 0;
  int n = 0;
  for (int p = 0; p < P.size(); ++p) {
    const double* x = P.position(p);
    if (x[0] >= 4 - 1e-9 && x[0] <= 6 + 1e-9 && std::fabs(x[1] - 10) < 1e-9)
      sum += sim.displacement()[2 * p + 1], ++n;
  }
  ASSERT_GT(n, 0);
  const auto& rows = sim.series();
  ASSERT_GT(rows.size(), 2u);
  ASSERT_EQ(rows.back().probes.size(), 1u);
  EXPECT_EQ(rows.back().step, r.dynamics->last_step);
  EXPECT_NEAR(rows.back().probes[0], sum / n, 1e-15 * std::fabs(sum / n));
  EXPECT_EQ(rows.front().probes[0], 0.0);  // at rest at iteration 0
  // ... and in energies.csv, a column named after it.
  std::ifstream csv(dir / "energies.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "step,time,strain,residual_ratio,broken_bonds,top_uy");
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, static_cast<int>(rows.size()));
}

// A matrix-free run logs one "linear solver:" line that says what ran; the short-horizon
// preconditioner's own factorisation is an indented line of its own, without the
// int64 maximum it is given as a size limit.
TEST(RunSummary, MatrixFreeRunLogsOneLinearSolverLine) {
  std::ifstream in(scene_path("crack.yaml"));
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const std::size_t at = yaml.find("count: 80");
  ASSERT_NE(at, std::string::npos);
  yaml.replace(at, 9, "count: 40");
  yaml += "solver: {linear: matrix_free, preconditioner: short_horizon}\n";
  Captured c;
  pd::Simulation sim(pd::parse_scene(yaml, "crack40.yaml"), c.sink());
  sim.run(false);
  int linear_lines = 0, factor_lines = 0;
  std::istringstream lines(c.log);
  for (std::string line; std::getline(lines, line);) {
    if (line.find("linear solver:") != std::string::npos) {
      ++linear_lines;
      EXPECT_EQ(line.rfind("  linear solver: matrix-free", 0), 0u) << line;
    }
    if (line.rfind("  preconditioner factor: ", 0) == 0) ++factor_lines;
  }
  EXPECT_EQ(linear_lines, 1) << c.log;
  EXPECT_EQ(factor_lines, 1) << c.log;
  EXPECT_EQ(c.log.find("9223372036854775807"), std::string::npos) << c.log;
}
