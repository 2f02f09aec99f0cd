// Dynamic fracture of the pre-notched plate (scenes/notched_plate.yaml), restarts from
// a checkpoint, and effects that a scene does not call for staying out of the run.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "damage/critical_stretch.hpp"
#include "input/scene.hpp"
#include "run/dynamic_simulation.hpp"
#include "run/simulation.hpp"
#include "temp_files.hpp"

namespace {
std::string scene_path(const char* name) { return std::string(PD_SOURCE_DIR) + "/scenes/" + name; }
std::string temp_dir(const char* name) {
  const auto d = pd::test::scratch_path(std::string("pd_dynamics_") + name);
  return d.string();
}
// The damage of every particle right after the notch is cut (no step taken).
std::vector<double> initial_damage(const pd::Scene& s) {
  pd::Scene zero = s;
  zero.dynamics->steps = 1;
  pd::DynamicSimulation sim(zero, [](const std::string&) {});
  return pd::particle_damage(sim.bonds());
}
}  // namespace

TEST(Fracture, DamageGrowsFromTheNotchTipOnlyAndMakesAnAnimation) {
  pd::Scene s = pd::read_scene(scene_path("notched_plate.yaml"));
  s.output.directory = temp_dir("fracture");
  const std::vector<double> before = initial_damage(s);
  const double tip[2] = {0.02, 0.025}, delta = s.delta();

  // Early time (step 80, 16.7 us: the load has reached the notch and the crack has just
  // started): every particle whose damage grew lies within 2 delta of the notch tip.
  {
    pd::Scene early = s;
    early.dynamics->steps = 80;
    pd::DynamicSimulation sim(early, [](const std::string&) {});
    sim.run(false);
    const std::vector<double> after = pd::particle_damage(sim.bonds());
    int grown = 0;
    for (int p = 0; p < sim.particles().size(); ++p) {
      if (after[p] <= before[p]) continue;
      ++grown;
      const double* x = sim.particles().position(p);
      EXPECT_LT(std::hypot(x[0] - tip[0], x[1] - tip[1]), 2 * delta)
          << "particle " << p << " at " << x[0] << ", " << x[1];
    }
    EXPECT_GT(grown, 0) << "no damage growth by step 80";
  }
  // The full run: the crack has run ahead of the tip along the notch line, the damage
  // stays in a band about it, and the snapshots form a .pvd animation.
  pd::DynamicSimulation sim(s, [](const std::string&) {});
  const pd::RunSummary r = sim.run(true);
  EXPECT_GT(r.dynamics->bonds_broken, 0);
  const std::vector<double> after = pd::particle_damage(sim.bonds());
  double front = 0;
  for (int p = 0; p < sim.particles().size(); ++p) {
    if (after[p] <= before[p]) continue;
    const double* x = sim.particles().position(p);
    front = std::max(front, x[0]);
    EXPECT_LT(std::fabs(x[1] - tip[1]), 2 * delta) << "damage off the crack line at " << x[0] << ", " << x[1];
  }
  EXPECT_GT(front, tip[0] + 5 * s.h);
  std::ifstream pvd(s.output.directory + "/animation.pvd");
  ASSERT_TRUE(pvd.good());
  std::stringstream text;
  text << pvd.rdbuf();
  int entries = 0;
  for (std::size_t at = text.str().find("<DataSet"); at != std::string::npos;
       at = text.str().find("<DataSet", at + 1))
    ++entries;
  EXPECT_EQ(entries, 16);  // steps 0, 10, ..., 150
  EXPECT_TRUE(std::filesystem::exists(s.output.directory + "/snapshots/step_00000150.vtu"));
}

TEST(Restart, StoppedAndRestartedRunEndsBitForBitLikeAnUninterruptedOne) {
  // With damage (bond state in the checkpoint), time-dependent loads and energies.
  pd::Scene s = pd::read_scene(scene_path("notched_plate.yaml"));
  s.dynamics->snapshot_every = 0;
  s.output.directory = temp_dir("restart_full");
  s.dynamics->checkpoint_every = 0;
  pd::DynamicSimulation full(s, [](const std::string&) {});
  const pd::RunSummary a = full.run(false);

  pd::Scene stopped = s;
  stopped.output.directory = temp_dir("restart_parts");
  stopped.dynamics->checkpoint_every = 50;
  {
    pd::DynamicSimulation first(stopped, [](const std::string&) {});
    first.run(false, 120);  // stopped at step 120: the last checkpoint is step 100
  }
  pd::Scene resumed = stopped;
  resumed.dynamics->restart = stopped.output.directory + "/checkpoint.bin";
  pd::DynamicSimulation second(resumed, [](const std::string&) {});
  const pd::RunSummary b = second.run(false);
  EXPECT_EQ(b.dynamics->first_step, 100);
  EXPECT_EQ(b.dynamics->last_step, a.dynamics->last_step);
  ASSERT_GT(a.dynamics->bonds_broken, 0);
  EXPECT_EQ(full.displacement(), second.displacement());  // bit for bit
  EXPECT_EQ(full.velocity(), second.velocity());
  EXPECT_EQ(full.bonds().alpha, second.bonds().alpha);
  EXPECT_EQ(a.dynamics->external_work, b.dynamics->external_work);
  EXPECT_EQ(a.dynamics->kinetic, b.dynamics->kinetic);
  EXPECT_EQ(a.dynamics->bonds_broken, b.dynamics->bonds_broken);
  ASSERT_EQ(full.series().size(), second.series().size());
  for (std::size_t i = 0; i < full.series().size(); ++i) {
    EXPECT_EQ(full.series()[i].step, second.series()[i].step);
    EXPECT_EQ(full.series()[i].kinetic, second.series()[i].kinetic);
    EXPECT_EQ(full.series()[i].external_work, second.series()[i].external_work);
  }
}

TEST(Effects, WhatTheSceneDoesNotCallForIsAbsent) {
  // The wave bar: no damage, no crack, no damping, no loads.
  pd::Scene wave = pd::read_scene(scene_path("wave_bar.yaml"));
  wave.dynamics->steps = 2;
  pd::DynamicSimulation w(wave, [](const std::string&) {});
  const pd::RunSummary rw = w.run(false);
  EXPECT_EQ(rw.variant, "intact (alpha folded to 1)");
  EXPECT_TRUE(w.assembler().intact());
  EXPECT_EQ(w.damage(), nullptr);
  EXPECT_TRUE(w.has_masses());
  for (const char* absent : {"damage", "crack", "damping", "external loads", "relaxation"}) {
    EXPECT_EQ(rw.text().find(absent), std::string::npos) << absent;
    EXPECT_EQ(rw.json().find(absent), std::string::npos) << absent;
  }
  EXPECT_NE(rw.text().find("inertia"), std::string::npos);

  // Relaxation: no mass or velocity arrays (the fictitious density replaces them).
  pd::DynamicSimulation relax(pd::read_scene(scene_path("relaxation_uniaxial.yaml")),
                              [](const std::string&) {});
  const pd::RunSummary rr = relax.run(false);
  EXPECT_FALSE(relax.has_masses());
  EXPECT_TRUE(relax.velocity().empty());
  EXPECT_EQ(rr.text().find("inertia"), std::string::npos);

  // A static scene: no dynamics block, no inertia, no damage.
  pd::Simulation stat(pd::read_scene(scene_path("uniaxial.yaml")), [](const std::string&) {});
  const pd::RunSummary rs = stat.run(false);
  EXPECT_FALSE(rs.dynamics.has_value());
  for (const char* absent : {"inertia", "damage", "dynamics", "relaxation"})
    EXPECT_EQ(rs.json().find(absent), std::string::npos) << absent;

  // The notched plate calls for damage: the damaged kernels from the start.
  pd::Scene plate = pd::read_scene(scene_path("notched_plate.yaml"));
  plate.dynamics->steps = 1;
  pd::DynamicSimulation p(plate, [](const std::string&) {});
  const pd::RunSummary rp = p.run(false);
  EXPECT_EQ(rp.variant, "damaged (reads alpha)");
  ASSERT_NE(p.damage(), nullptr);
  EXPECT_NE(rp.text().find("critical-stretch"), std::string::npos);
}
