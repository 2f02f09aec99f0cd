// Explicit dynamics over the ranks: the serial run's set-up (run/dynamic_run.hpp) and
// velocity Verlet, each rank stepping its own particles. Per step: the first half step on the owned free dofs,
// the prescribed motion, one ghost update of u (PETSc's forward scatter), bonds over the
// limit broken in the rank's own families, their forces summed into the owners (the
// reverse scatter with addition), the second half step. A bond shared by two ranks
// breaks on both: each holds the same bits of u at both ends after the ghost update and
// the rule is symmetric bit for bit (damage/critical_stretch.cpp). Rank 0 gathers u, v
// and the factors alpha when the serial run would read them (a series row, a snapshot,
// a checkpoint, the end) and writes through the serial run's own functions.
#include <fmt/core.h>
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "damage/critical_stretch.hpp"
#include "dynamics/energies.hpp"
#include "dynamics/progress.hpp"
#include "dynamics/verlet_integrator.hpp"
#include "petsc/distributed_dynamics.hpp"
#include "petsc/rank_steps.hpp"
#include "run/dynamic_run.hpp"
#include "run/run_outputs.hpp"
#include "solve/stopwatch.hpp"

namespace pd {

namespace {

class DistributedExplicit {
 public:
  explicit DistributedExplicit(DynamicRun& run) : s_(run), steps_(run), part_(steps_.partition()) {}
  RunSummary run(bool write, int stop_after);

 private:
  DynamicRun& s_;
  RankSteps steps_;
  const Partition& part_;
};

RunSummary DistributedExplicit::run(bool write, int stop_after) {
  const auto t0 = std::chrono::steady_clock::now();
  RunSummary& summary = s_.summary;
  DynamicsReport& rep = s_.start_report();
  const DynamicsSpec& dyn = *s_.scene.dynamics;
  const bool root = steps_.root();
  write = write && root;
  // The set-up ran on every rank from the same scene: its stable step must agree.
  const double dt = s_.dt();
  double dt_max = 0, dt_min = 0;
  MPI_Allreduce(&dt, &dt_max, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  MPI_Allreduce(&dt, &dt_min, 1, MPI_DOUBLE, MPI_MIN, PETSC_COMM_WORLD);
  if (dt_max != dt_min) throw std::logic_error(fmt::format("the ranks' time steps differ ({:.17g} .. {:.17g})", dt_min, dt_max));
  const std::string line = fmt::format(
      "distributed: velocity Verlet over {} MPI ranks (PETSc), rank 0 owns {} particles and {} ghosts; one ghost update "
      "per step",
      part_.ranks, part_.owned(), part_.ghosts.size());
  summary.effects.push_back(line);
  s_.log("  effect: " + line);

  rep.dt = dt, rep.dt_stable = s_.model.inertia->dt_stable, rep.damping = dyn.damping;
  rep.dt_rule = dyn.dt > 0 ? "fixed" : fmt::format("{} x the stable estimate", dyn.safety_factor);
  ExternalWork work;  // this rank's dofs; the total is summed when a row or checkpoint needs it
  int step = 0;
  long long broken_start = broken_bond_count(s_.model.bonds);
  if (!dyn.restart.empty()) {
    std::vector<double> scalars;
    s_.restore(dyn.restart, step, scalars);  // every rank reads the whole (serial-format) state
    if (scalars.size() < 2) throw std::runtime_error(dyn.restart + ": the checkpoint has no energy accumulators");
    if (root) work.restore(scalars[0]);
    broken_start = static_cast<long long>(scalars[1]);
  } else {
    s_.apply_initial_conditions();
    s_.prescribe(0.0);
    s_.after_step();  // the whole initial state is on every rank: the serial call is exact here
  }
  rep.first_step = step;
  const int last = stop_after > 0 ? std::min(stop_after, dyn.steps) : dyn.steps;
  const VerletIntegrator verlet(*s_.model.inertia, s_.model.damping, steps_.owned_free(), dt);
  std::vector<double> f, g, g_old, u_old;
  double t = step * dt;
  steps_.forces(t, f, g);
  auto record = [&](int st) {
    const double w = steps_.sum(work.value());
    if (!root) return;
    SeriesRow r = s_.make_row(st, t, 0.0);
    r.external_work = w;
    s_.series.push_back(r);
  };
  if (step == 0) {
    steps_.gather();
    record(0);
    if (dyn.snapshot_every > 0 && write) s_.write_snapshot(0, 0.0);
  }
  Progress progress(s_.log, write ? dyn.progress_seconds : 0.0, step, last);
  for (int st = step + 1; st <= last; ++st) {
    steps_.agree_on_interrupt(fmt::format("at time step {} of {}", st, last));
    u_old = s_.u;
    g_old = g;
    verlet.first_half(s_.u, s_.v, f);
    t = st * dt;
    s_.prescribe(t);
    steps_.ghost_update();
    steps_.break_bonds();
    steps_.forces(t, f, g);
    verlet.second_half(s_.v, f);
    work.add(g_old, g, u_old, s_.u);
    const bool row = st % dyn.output_every == 0 || st == dyn.steps;
    const bool snapshot = dyn.snapshot_every > 0 && (st % dyn.snapshot_every == 0 || st == dyn.steps);
    const bool checkpoint = dyn.checkpoint_every > 0 && st % dyn.checkpoint_every == 0;
    if (row || snapshot || checkpoint) steps_.gather();
    if (row) record(st);
    if (write && snapshot) s_.write_snapshot(st, t);
    if (checkpoint) {
      const double w = steps_.sum(work.value());
      if (root) s_.save_checkpoint(st, {w, static_cast<double>(broken_start)});
    }
    progress.update(st, t);
  }
  steps_.gather();
  steps_.check_finite(fmt::format("the displacement is not finite (unstable time step? dt = {:.6g})", dt));
  const double total_work = steps_.sum(work.value());
  rep.last_step = last;
  rep.time = last * dt;
  rep.external_work = total_work;
  rep.strain_available = s_.model.assembler->has_energy();
  if (root) {
    const SeriesRow end = s_.make_row(last, rep.time, 0.0);
    rep.kinetic = end.kinetic;
    rep.strain = end.strain;
    rep.bonds_broken = broken_bond_count(s_.model.bonds) - broken_start;
    summary.broken_bonds = static_cast<int>(broken_bond_count(s_.model.bonds));
    const std::vector<double> stress = s_.stress_field();
    summary.probes = evaluate_probes(s_.scene, s_.model.particles, s_.probe_ids, s_.u, &stress);
  }
  summary.solve_seconds = seconds_since(t0);
  if (write) s_.write_results();
  s_.log(summary.text());
  return summary;
}

}  // namespace

RunSummary run_distributed_explicit(DynamicRun& run, bool write, int stop_after) {
  DistributedExplicit distributed(run);
  return distributed.run(write, stop_after);
}

}  // namespace pd
