// Explicit dynamic fracture over this run's ranks (1, 2 or 3) against the serial driver:
// the notched glass plate (scenes/notched_plate.yaml, coarsened) breaks the same bonds
// and ends at the same displacement and velocity. Every rank's own families must hold
// the serial factors, and rank 0's gathered factors must be symmetric (a bond's two
// copies, held by the ranks owning its two particles, broken together).
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "damage/critical_stretch.hpp"
#include "exec/serial_steps.hpp"
#include "input/scene.hpp"
#include "model/model.hpp"
#include "petsc/partition.hpp"
#include "relative_difference.hpp"
#include "run/dynamic_run.hpp"

namespace pd {
namespace {

Scene scene(const std::string& name, const std::vector<std::pair<std::string, std::string>>& edits) {
  std::ifstream in(std::string(PD_SOURCE_DIR) + "/scenes/" + name);
  std::ostringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  for (const auto& [from, to] : edits) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  return parse_scene(text, name);
}

Scene notched_plate() {
  return scene("notched_plate.yaml", {{"count: 50", "count: 24"},
                                      {"steps: 150", "steps: 80"},
                                      {"snapshot_every: 10", "snapshot_every: 0"},
                                      {"checkpoint_every: 50", "checkpoint_every: 0"}});
}

// The same scene on the PETSc backend: run_dynamic then steps each rank's own particles.
Scene on_ranks(Scene scene) {
  scene.solver.backend = Backend::petsc;
  return scene;
}

using pd::test::relative_difference;

// Runs `make()` serially and over the ranks; checks the bonds and the state agree.
template <class MakeScene>
void expect_same_fracture(MakeScene make, long long min_broken) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const Scene scene_s = make(), scene_d = on_ranks(make());
  Model model_s = build_dynamic_model(scene_s), model_d = build_dynamic_model(scene_d);
  DynamicRun serial = prepare_dynamic_run(model_s, scene_s, [](const std::string&) {});
  const RunSummary ss = run_dynamic(serial, false);
  DynamicRun distributed = prepare_dynamic_run(model_d, scene_d, [](const std::string&) {});
  const RunSummary s = run_dynamic(distributed, false);

  // Each rank's own families hold the serial run's factors, bit for bit.
  const Bonds& bs = model_s.bonds;
  const Bonds& bd = model_d.bonds;
  const Partition part = make_partition(model_d.particles, bd, rank, ranks);
  int differing = 0;
  for (int i = 0; i < part.owned(); ++i) {
    const int p = part.owned_particle(i);
    for (int e = bd.offsets[p]; e < bd.offsets[p + 1]; ++e) differing += bd.alpha[e] != bs.alpha[e];
  }
  EXPECT_EQ(differing, 0) << "rank " << rank;
  if (rank != 0) return;
  // The crack ran: the pre-notch cut some bonds, the loads broke many more.
  const long long broken = broken_bond_count(bs);
  EXPECT_GT(s.dynamics->bonds_broken, min_broken) << "the test must exercise fracture";
  EXPECT_EQ(s.dynamics->bonds_broken, ss.dynamics->bonds_broken);
  EXPECT_EQ(bd.alpha, bs.alpha);
  EXPECT_EQ(s.broken_bonds, broken);
  for (int p = 0; p < bd.particle_count(); ++p)
    for (int e = bd.offsets[p]; e < bd.offsets[p + 1]; ++e) {
      const int q = bd.neighbor[e];
      bool partner = false;
      for (int k = bd.offsets[q]; k < bd.offsets[q + 1]; ++k)
        if (bd.neighbor[k] == p) partner = partner || bd.alpha[k] == bd.alpha[e];
      ASSERT_TRUE(partner) << "bond " << p << "-" << q << " broken in one family only";
    }
  // The forces are summed in another order than the serial assembler's (the owner's
  // family, then the ghost copies' contributions): rounding, 1e-16 relative per step,
  // grown by the fracture's sensitivity over 80 steps (measured 1.0e-13 for u and 2.4e-12 for v at 1, 2
  // and 3 ranks, 274 bonds broken); 1e-10 is far below any physical change.
  EXPECT_LT(relative_difference(serial.u, distributed.u), 1e-10);
  EXPECT_LT(relative_difference(serial.v, distributed.v), 1e-10);
  ASSERT_EQ(serial.series.size(), distributed.series.size());
  for (std::size_t k = 0; k < serial.series.size(); ++k) {
    EXPECT_EQ(serial.series[k].broken_bonds, distributed.series[k].broken_bonds) << "row " << k;
    EXPECT_NEAR(serial.series[k].kinetic, distributed.series[k].kinetic,
                1e-10 * serial.series[k].kinetic + 1e-300);
  }
}

TEST(DistributedDynamics, NotchedPlateFractureEqualsSerial) { expect_same_fracture(notched_plate, 100); }

// The notched 3D bar (scenes/notched_bar_3d.yaml) at spacing 2 mm for 100 steps (33 us):
// the crack has left the notch (the full scene's separation is in docs/scaling.md).
TEST(DistributedDynamics, NotchedBar3DFractureEqualsSerial) {
  expect_same_fracture(
      [] {
        return scene("notched_bar_3d.yaml",
                     {{"spacing: 0.001 ", "spacing: 0.002 "}, {"steps: 300", "steps: 100"}});
      },
      200);
}

// Adaptive dynamic relaxation over the ranks against the serial iteration. Unlike the
// explicit runs, the trajectory is not reproduced to rounding: the damping coefficient
// c = 2 sqrt(u'K1u / u'u) divides force differences by small velocities, and the
// residual near convergence is a difference of nearly equal forces, so the 1e-16
// differences of another summation order grow (measured on the uniaxial scene: the
// residual ratio at iteration 100 differs by 1.5e-6 relative even on one rank, whose
// Morton order sums in another order than the serial loop). Both runs stop inside the
// tolerance ball of the same static answer, so what must hold is: the distributed answer
// is converged by the serial driver's own residual, and it is the serial displacement to
// 1e-8 relative (issue 18's criterion; measured 2.1e-10 to 4.6e-10 at 1, 2 and 3 ranks on the
// uniaxial scene, 5.0e-13 to 4.8e-10 on the cube).
template <class MakeScene>
void expect_same_relaxation(MakeScene make) {
  const Scene scene_s = make(), scene_d = on_ranks(make());
  Model model_s = build_dynamic_model(scene_s), model_d = build_dynamic_model(scene_d);
  DynamicRun serial = prepare_dynamic_run(model_s, scene_s, [](const std::string&) {});
  const RunSummary ss = run_dynamic(serial, false);
  DynamicRun distributed = prepare_dynamic_run(model_d, scene_d, [](const std::string&) {});
  const RunSummary s = run_dynamic(distributed, false);
  ASSERT_TRUE(ss.dynamics->converged);
  EXPECT_TRUE(s.dynamics->converged);
  EXPECT_GT(ss.dynamics->last_step, 50) << "the test must exercise the iteration";
  // The iteration count is not compared: it moves with rounding (uniaxial 296 serially,
  // 296-297 over the ranks; the 3D cube 1 179 serially, 854-1 295 over 1-3 ranks).
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) return;
  // The serial driver's residual at the gathered answer, against the serial reference
  // (the loads' norm here: the body starts at rest, so the initial residual is the loads).
  const std::vector<int>& free = model_s.dofs.free_dofs();
  std::vector<double> f, g, load(serial.u.size(), 0.0);
  const std::vector<double> u_serial = serial.u;
  serial.u = distributed.u;
  SerialSteps(StepState{model_s, serial.u, serial.v, scene_s.file}).forces(0.0, f, g);
  serial.u = u_serial;
  for (const auto& e : model_s.effects)
    if (e->is_load()) e->add_forces(u_serial.data(), 0.0, load.data());
  double r = 0, ref = 0;
  for (int i : free) r += f[i] * f[i], ref += load[i] * load[i];
  EXPECT_LE(std::sqrt(r / ref), scene_s.dynamics->tolerance);
  EXPECT_LT(relative_difference(serial.u, distributed.u), 1e-8);
  ASSERT_EQ(s.probes.size(), ss.probes.size());
  for (std::size_t k = 0; k < ss.probes.size(); ++k)
    EXPECT_NEAR(s.probes[k].value, ss.probes[k].value, 1e-8 * std::abs(ss.probes[k].value))
        << ss.probes[k].name;
}

// scenes/relaxation_uniaxial.yaml (2D, 400 particles): the loads' reference and the
// constrained sides cross the rank boundaries.
TEST(DistributedRelaxation, UniaxialEqualsSerial) {
  expect_same_relaxation([] { return scene("relaxation_uniaxial.yaml", {}); });
}

// The cube in tension (3D, scenes/cube_tension.yaml, 729 particles, Silling) relaxed
// instead of solved by Newton. Its supports are minimal (a face on rollers, two edge lines),
// so it is worse conditioned than the uniaxial plate: at tolerance 1e-8 two runs that both
// meet it differ by 4.9e-7 in u, even on one rank. At 1e-11 (1 179 serial iterations) the
// tolerance ball is small enough for the 1e-8 comparison.
TEST(DistributedRelaxation, CubeTension3DEqualsSerial) {
  expect_same_relaxation([] {
    return scene("cube_tension.yaml",
                 {{"output: {directory: out/cube_tension}",
                   "output: {directory: out/cube_tension}\ndynamics: {method: relaxation, tolerance: "
                   "1.0e-11, steps: 20000, output_every: 100}"}});
  });
}

}  // namespace
}  // namespace pd
