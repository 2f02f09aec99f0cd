// A relaxation (ADR) run stopped and restarted from its checkpoint ends where an
// uninterrupted one ends: same iteration, same displacement and bonds bit for bit, same
// time series and broken-bond count. Displacement-driven with damage, so the reference
// force is the initial out-of-balance force (not the loads) and bonds break on the way.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "input/scene.hpp"
#include "run/dynamic_simulation.hpp"
#include "temp_files.hpp"

namespace {
void quiet(const std::string&) {}

pd::Scene relaxation_scene(const char* name) {
  pd::Scene s = pd::read_scene(std::string(PD_SOURCE_DIR) + "/scenes/notched_plate_static.yaml");
  pd::DynamicsSpec d;
  d.method = pd::DynamicsMethod::relaxation;
  d.steps = 100000;
  d.output_every = 100;
  d.progress_seconds = 0;
  d.threads = 1;
  s.dynamics = d;
  const auto dir = pd::test::scratch_path(std::string("pd_relaxation_") + name);
  s.output.directory = dir.string();
  return s;
}
}  // namespace

TEST(RelaxationRestart, StoppedAndRestartedRunEndsLikeAnUninterruptedOne) {
  pd::DynamicSimulation full(relaxation_scene("full"), quiet);
  const pd::RunSummary a = full.run(false);
  ASSERT_TRUE(a.dynamics->converged);
  ASSERT_GT(a.dynamics->bonds_broken, 0);
  const int stop = a.dynamics->last_step - 100,
            every = (stop - 50) / 2;  // two checkpoints, then run on past the last
  ASSERT_GT(every, 100);

  pd::Scene parts = relaxation_scene("parts");
  parts.dynamics->checkpoint_every = every;
  {
    pd::DynamicSimulation first(parts, quiet);
    const pd::RunSummary stopped = first.run(false, stop);
    ASSERT_FALSE(stopped.dynamics->converged);
  }
  parts.dynamics->restart = parts.output.directory + "/checkpoint.bin";
  pd::DynamicSimulation second(parts, quiet);
  const pd::RunSummary b = second.run(false);
  EXPECT_EQ(b.dynamics->first_step, 2 * every);
  ASSERT_TRUE(b.dynamics->converged);
  EXPECT_EQ(b.dynamics->last_step, a.dynamics->last_step);
  EXPECT_EQ(full.displacement(), second.displacement());  // bit for bit
  EXPECT_EQ(full.bonds().alpha, second.bonds().alpha);
  EXPECT_EQ(b.dynamics->residual_ratio, a.dynamics->residual_ratio);
  EXPECT_EQ(b.dynamics->bonds_broken, a.dynamics->bonds_broken);
  EXPECT_EQ(b.broken_bonds, a.broken_bonds);
  ASSERT_EQ(full.series().size(), second.series().size());
  for (std::size_t i = 0; i < full.series().size(); ++i) {
    EXPECT_EQ(full.series()[i].step, second.series()[i].step);
    EXPECT_EQ(full.series()[i].residual_ratio, second.series()[i].residual_ratio) << "row " << i;
    EXPECT_EQ(full.series()[i].broken_bonds, second.series()[i].broken_bonds) << "row " << i;
  }
}
