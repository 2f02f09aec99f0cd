// Adaptive dynamic relaxation to the static answer, one loop for every backend
// (exec/step_executor.hpp). Per iteration: the ADR update of the free dofs this process
// moves (its damping's two sums summed over the processes), the fictitious layers
// following the body, the ghost update of u, every effect's after_step, the forces, and
// the out-of-balance norm for the convergence test (summed over the processes, so every
// one stops at the same iteration). The fictitious density comes from the set-up, which
// every process runs on the whole model: the processes check that theirs agree. Rank 0
// gathers u and the bond factors when a series row, snapshot or checkpoint is due; a
// checkpoint also gathers ADR's velocity and previous force, so it is the serial format
// and restarts with any process count.
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "constraints/constraints.hpp"
#include "damage/critical_stretch.hpp"
#include "dynamics/dynamic_relaxation.hpp"
#include "dynamics/progress.hpp"
#include "effects/inertia.hpp"
#include "exec/step_executor.hpp"
#include "run/dynamic_run.hpp"
#include "run/relaxation_state.hpp"
#include "stopwatch.hpp"

namespace pd {

namespace {
double density_sum(const std::vector<double>& density) {
  double s = 0;
  for (double d : density) s += d;  // the same order on every process: equal bits when equal densities
  return s;
}

struct RelaxationStart {
  int step = 0;
  long long broken_start = 0;
  double reference = 0;
};

// From the checkpoint the scene names (every process reads the whole, serial-format state),
// or from the initial conditions; f: the out-of-balance force there.
RelaxationStart start_relaxation(DynamicRun& run, StepExecutor& exec, AdaptiveDynamicRelaxation& adr,
                                 std::vector<double>& f, std::vector<double>& g,
                                 const std::function<double(const std::vector<double>&)>& norm) {
  const DynamicsSpec& dyn = *run.scene.dynamics;
  RelaxationStart start{0, broken_bond_count(run.model.bonds), 0.0};
  if (!dyn.restart.empty()) {
    std::vector<double> scalars;
    run.restore(dyn.restart, start.step, scalars);
    RelaxationRestart state = relaxation_restart(scalars, run.u.size(), dyn.restart);
    adr.restore(state.iterations, std::move(state.v), std::move(state.f_prev));
    start.reference = state.reference;
    start.broken_start = state.broken_start;
    exec.forces(0.0, f, g);
  } else {
    run.apply_initial_conditions();
    run.prescribe(0.0);
    exec.forces(0.0, f, g);
    start.reference = relaxation_reference(run.model, run.u, f, norm);
  }
  return start;
}
}  // namespace

RunSummary run_relaxation(DynamicRun& run, bool write, int stop_after) {
  const Scene& scene = run.scene;
  const Model& model = run.model;
  std::vector<double>& u = run.u;
  const auto t0 = std::chrono::steady_clock::now();
  const DynamicsSpec& dyn = *scene.dynamics;
  DynamicsReport& rep = run.start_report();
  rep.dt = 1;
  check_scene_holds_body(scene, model.particles, model.bonds, model.dofs);
  const auto steps = run.make_steps();
  StepExecutor& exec = *steps;
  const bool root = exec.root();
  write = write && root;
  exec.check_agrees(density_sum(model.inertia->mass()), "fictitious densities (sums)");
  run.add_effect_line(exec.describe("adaptive dynamic relaxation", "iteration",
                                    ", the damping and the residual norm summed over the ranks"));
  AdaptiveDynamicRelaxation adr(model.inertia->mass(), exec.free_dofs(),
                                [&exec](double* values, int count) { exec.sum_in_place(values, count); });
  std::vector<double> f, g;
  const std::function<double(const std::vector<double>&)> norm = [&](const std::vector<double>& v) {
    return std::sqrt(exec.free_square_sum(v));
  };
  const auto [step, broken_start, reference] = start_relaxation(run, exec, adr, f, g, norm);
  rep.first_step = step;
  const int last = stop_after > 0 ? std::min(stop_after, dyn.steps) : dyn.steps;
  double ratio = norm(f) / reference;
  if (step == 0) {
    exec.gather();
    if (root) run.series.push_back(run.make_row(0, 0, ratio));
  }
  Progress progress(run.log, write ? dyn.progress_seconds : 0.0, step, last);
  int s = step;
  while (ratio > dyn.tolerance && s < last) {
    exec.check_interrupt(fmt::format("at relaxation iteration {} of at most {}", s + 1, last));
    ++s;
    adr.step(f, u);
    model.dofs.apply_ties(u.data(), 1.0);  // a fictitious layer follows the body's update
    exec.sync();
    exec.after_step();
    exec.forces(0.0, f, g);
    ratio = norm(f) / reference;  // the same on every process: all stop together
    if (!std::isfinite(ratio))
      throw std::runtime_error(fmt::format("adaptive dynamic relaxation diverged at iteration {}", s));
    const bool done = ratio <= dyn.tolerance;
    const bool row = s % dyn.output_every == 0 || done;
    const bool snapshot = dyn.snapshot_every > 0 && (s % dyn.snapshot_every == 0 || done);
    const bool checkpoint = dyn.checkpoint_every > 0 && s % dyn.checkpoint_every == 0;
    if (row || snapshot || checkpoint) exec.gather();
    if (row && root) run.series.push_back(run.make_row(s, s, ratio));
    if (write && snapshot) run.write_snapshot(s, s);
    if (checkpoint) {
      RelaxationRestart state{adr.iterations(), reference, broken_start, adr.velocity(),
                              adr.previous_force()};
      exec.gather({&state.v, &state.f_prev});
      if (root) run.save_checkpoint(s, relaxation_scalars(state));
    }
    progress.update(s, s, fmt::format(", |r|/ref = {:.3e}", ratio));
  }
  exec.gather();
  rep.last_step = s;
  rep.time = s;
  rep.converged = ratio <= dyn.tolerance;
  // A law with memory: relaxation is one load step from the virgin body, so every iterate
  // read the committed (initial) history, as Newton's single step does; the converged
  // answer stands and is committed once, for the outputs.
  if (rep.converged) exec.commit_history();
  rep.residual_ratio = ratio;
  rep.damping = adr.damping();
  rep.strain_available = model.assembler->has_energy();
  if (rep.strain_available && root) rep.strain = model.assembler->strain_energy(u.data());
  run.summary.newton.converged = rep.converged;
  run.log(fmt::format("  relaxation: {} after {} iterations, |r|/ref = {:.3e}",
                      rep.converged ? "converged" : "not converged", s, ratio));
  RunSummary summary = root ? run.finish(broken_start, t0, write) : run.finish_elsewhere(t0);
  if (!rep.converged && stop_after == 0)
    throw std::runtime_error(fmt::format(
        "adaptive dynamic relaxation did not converge in {} iterations (|r|/ref = {:.3e} > {:.3g})", s, ratio,
        dyn.tolerance));
  return summary;
}

}  // namespace pd
