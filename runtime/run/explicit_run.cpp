// Explicit dynamics: velocity Verlet from t = 0 (or a checkpoint) to the last step, one
// loop for every backend (exec/step_executor.hpp). Per step: the first half step on the
// free dofs this process steps, the prescribed motion, the ghost update of u (nothing
// serially), every effect's after_step (damage: bonds over the limit break), the forces,
// the second half step. Under PETSc each rank steps its own particles, and rank 0 gathers
// u, v and the bond factors when a series row, snapshot, checkpoint or the end reads them,
// and writes through the serial run's functions.
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "damage/critical_stretch.hpp"
#include "dynamics/energies.hpp"
#include "dynamics/progress.hpp"
#include "dynamics/verlet_integrator.hpp"
#include "exec/step_executor.hpp"
#include "run/dynamic_run.hpp"
#include "stopwatch.hpp"

namespace pd {

namespace {
struct ExplicitStart {
  int step = 0;
  long long broken_start = 0;
};

// From the checkpoint the scene names (every process reads the whole, serial-format
// state; root alone restores the work, which the processes sum), or from the initial
// conditions at t = 0 with every effect's after_step there.
ExplicitStart start_explicit(DynamicRun& run, StepExecutor& exec, ExternalWork& work) {
  const DynamicsSpec& dyn = *run.scene.dynamics;
  ExplicitStart start{0, broken_bond_count(run.model.bonds)};
  if (!dyn.restart.empty()) {
    std::vector<double> scalars;
    run.restore(dyn.restart, start.step, scalars);
    if (scalars.size() < 2)
      throw std::runtime_error(dyn.restart + ": the checkpoint has no energy accumulators");
    if (exec.root()) work.restore(scalars[0]);
    start.broken_start = static_cast<long long>(scalars[1]);
  } else {
    run.apply_initial_conditions();
    run.prescribe(0.0);
    exec.after_step();
  }
  return start;
}
}  // namespace

RunSummary run_explicit(DynamicRun& run, bool write, int stop_after) {
  const Model& model = run.model;
  std::vector<double>& u = run.u;
  const auto steps = run.make_steps();
  StepExecutor& exec = *steps;
  const bool root = exec.root();
  write = write && root;
  const auto t0 = std::chrono::steady_clock::now();
  const DynamicsSpec& dyn = *run.scene.dynamics;
  DynamicsReport& rep = run.start_report();
  const double dt = run.dt();
  run.model.step_duration = dt;         // a rate-dependent law integrates its update over dt
  exec.check_agrees(dt, "time steps");  // the set-up ran on every process from the same scene
  run.add_effect_line(exec.describe("velocity Verlet", "step", ""));
  rep.dt = dt, rep.dt_stable = model.inertia->dt_stable, rep.damping = dyn.damping;
  rep.dt_rule = dyn.dt > 0 ? "fixed" : fmt::format("{} x the stable estimate", dyn.safety_factor);
  ExternalWork work;  // over this process's dofs; summed when a row, checkpoint or the end reads it
  const auto [step, broken_start] = start_explicit(run, exec, work);
  rep.first_step = step;
  const int last = stop_after > 0 ? std::min(stop_after, dyn.steps) : dyn.steps;
  const VerletIntegrator verlet(*model.inertia, model.damping, exec.free_dofs(), dt);
  std::vector<double> f, g, g_old, u_old;
  double t = step * dt;
  exec.forces(t, f, g);
  auto record = [&](int s) {
    const double w = exec.sum(work.value());
    if (!root) return;
    SeriesRow r = run.make_row(s, t, 0.0);
    r.external_work = w;
    run.series.push_back(r);
  };
  if (step == 0) {
    exec.gather();
    record(0);
    if (dyn.snapshot_every > 0 && write) run.write_snapshot(0, 0.0);
  }
  Progress progress(run.log, write ? dyn.progress_seconds : 0.0, step, last);
  for (int s = step + 1; s <= last; ++s) {
    exec.check_interrupt(fmt::format("at time step {} of {}", s, last));
    // The previous step stands: its history is committed before u moves, so the forces
    // of this step are the return map of u_s from h_(s-1), and a checkpoint written in
    // this step holds (u_s, h_(s-1)), from which a restart recomputes the same forces.
    exec.commit_history();
    u_old = u;
    g_old = g;
    verlet.first_half(u, run.v, f);
    t = s * dt;
    run.prescribe(t);
    exec.sync();
    exec.after_step();
    exec.forces(t, f, g);
    verlet.second_half(run.v, f);
    work.add(g_old, g, u_old, u);
    const bool row = s % dyn.output_every == 0 || s == dyn.steps;
    const bool snapshot = dyn.snapshot_every > 0 && (s % dyn.snapshot_every == 0 || s == dyn.steps);
    const bool checkpoint = dyn.checkpoint_every > 0 && s % dyn.checkpoint_every == 0;
    if (row || snapshot || checkpoint) exec.gather();
    if (row) record(s);
    if (write && snapshot) run.write_snapshot(s, t);
    if (checkpoint) {
      const double w = exec.sum(work.value());
      if (root) run.save_checkpoint(s, {w, static_cast<double>(broken_start)});
    }
    progress.update(s, t);
  }
  exec.gather();
  exec.check_finite(fmt::format("the displacement is not finite (unstable time step? dt = {:.6g})", dt));
  exec.commit_history();  // the last step stands too: the output fields read its history
  // ... at a zero duration, so they are the last step's forces (Model::step_duration).
  run.model.step_duration = 0.0;
  rep.last_step = last;
  rep.time = last * dt;
  rep.external_work = exec.sum(work.value());
  rep.strain_available = model.assembler->has_energy();
  if (!root) return run.finish_elsewhere(t0);
  const SeriesRow end = run.make_row(last, rep.time, 0.0);
  rep.kinetic = end.kinetic;
  rep.strain = end.strain;
  return run.finish(broken_start, t0, write);
}

}  // namespace pd
