// Adaptive dynamic relaxation over the ranks: the serial iteration (run/relaxation_run.cpp,
// dynamics/dynamic_relaxation.hpp) with each rank moving its own free dofs. Per
// iteration: the ADR update of the owned free dofs (its damping's two sums one
// all-reduce), one ghost update of u, bonds broken in the rank's own families, their
// forces summed into the owners, and the out-of-balance norm for the convergence test
// (one all-reduce), so every rank stops at the same iteration. The fictitious density
// comes from the set-up, which every rank runs on the whole (replicated) model: its row
// sums, and the largest of them for a row without stiffness, are the serial ones bit for
// bit, and the ranks check that they agree (MPI_MAX and MPI_MIN of its sum). Rank 0
// gathers u and the factors alpha when a series row, snapshot or checkpoint is due and
// writes the serial run's files; a checkpoint also gathers ADR's velocity and previous
// force, so it is the serial format and restarts with any rank count.
#include <fmt/core.h>
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "damage/critical_stretch.hpp"
#include "dynamics/dynamic_relaxation.hpp"
#include "dynamics/progress.hpp"
#include "effects/inertia.hpp"
#include "petsc/distributed_dynamics.hpp"
#include "petsc/rank_gather.hpp"
#include "petsc/rank_steps.hpp"
#include "run/constraints.hpp"
#include "run/dynamic_run.hpp"
#include "run/relaxation_state.hpp"
#include "solve/stopwatch.hpp"

namespace pd {

namespace {

// The set-up ran on every rank from the same scene: its fictitious density must agree.
void check_density_agrees(const std::vector<double>& density) {
  double local = 0, high = 0, low = 0;
  for (double d : density) local += d;  // the same order on every rank: equal bits when equal densities
  MPI_Allreduce(&local, &high, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  MPI_Allreduce(&local, &low, 1, MPI_DOUBLE, MPI_MIN, PETSC_COMM_WORLD);
  if (high != low) throw std::logic_error(fmt::format("the ranks' fictitious densities differ (sums {:.17g} .. {:.17g})", low, high));
}

void sum_over_ranks(double* values, int count) {
  MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
}

}  // namespace

RunSummary run_distributed_relaxation(DynamicRun& run, bool write, int stop_after) {
  const Scene& scene = run.scene;
  const Model& model = run.model;
  std::vector<double>& u = run.u;
  const auto t0 = std::chrono::steady_clock::now();
  const DynamicsSpec& dyn = *scene.dynamics;
  DynamicsReport& rep = run.start_report();
  rep.dt = 1;
  check_scene_holds_body(scene, model.particles, model.bonds, model.dofs);
  RankSteps steps(run);
  const Partition& part = steps.partition();
  const bool root = steps.root();
  write = write && root;
  check_density_agrees(model.inertia->mass());
  const std::string line = fmt::format(
      "distributed: adaptive dynamic relaxation over {} MPI ranks (PETSc), rank 0 owns {} particles and {} ghosts; one "
      "ghost update per iteration, the damping and the residual norm summed over the ranks",
      part.ranks, part.owned(), part.ghosts.size());
  run.summary.effects.push_back(line);
  run.log("  effect: " + line);

  AdaptiveDynamicRelaxation adr(model.inertia->mass(), steps.owned_free(), sum_over_ranks);
  int step = 0;
  long long broken_start = broken_bond_count(model.bonds);
  std::vector<double> f, g;
  double reference = 0;
  const auto norm = [&](const std::vector<double>& v) { return std::sqrt(steps.free_square_sum(v)); };
  if (!dyn.restart.empty()) {
    std::vector<double> scalars;
    run.restore(dyn.restart, step, scalars);  // every rank reads the whole (serial-format) state
    RelaxationRestart state = relaxation_restart(scalars, u.size(), dyn.restart);
    adr.restore(state.iterations, std::move(state.v), std::move(state.f_prev));
    reference = state.reference;
    broken_start = state.broken_start;
    steps.forces(0.0, f, g);
  } else {
    run.apply_initial_conditions();
    run.prescribe(0.0);
    steps.forces(0.0, f, g);
    reference = relaxation_reference(model, u, f, norm);
  }
  rep.first_step = step;
  const int last = stop_after > 0 ? std::min(stop_after, dyn.steps) : dyn.steps;
  double ratio = norm(f) / reference;
  if (step == 0) {
    steps.gather();
    if (root) run.series.push_back(run.make_row(0, 0, ratio));
  }
  Progress progress(run.log, write ? dyn.progress_seconds : 0.0, step, last);
  int s = step;
  while (ratio > dyn.tolerance && s < last) {
    steps.agree_on_interrupt(fmt::format("at relaxation iteration {} of at most {}", s + 1, last));
    ++s;
    adr.step(f, u);
    steps.ghost_update();
    steps.break_bonds();
    steps.forces(0.0, f, g);
    ratio = norm(f) / reference;  // the same on every rank: all stop together
    if (!std::isfinite(ratio)) throw std::runtime_error(fmt::format("adaptive dynamic relaxation diverged at iteration {}", s));
    const bool done = ratio <= dyn.tolerance;
    const bool row = s % dyn.output_every == 0 || done;
    const bool snapshot = dyn.snapshot_every > 0 && (s % dyn.snapshot_every == 0 || done);
    const bool checkpoint = dyn.checkpoint_every > 0 && s % dyn.checkpoint_every == 0;
    if (row || snapshot || checkpoint) steps.gather();
    if (row && root) run.series.push_back(run.make_row(s, s, ratio));
    if (write && snapshot) run.write_snapshot(s, s);
    if (checkpoint) {
      RelaxationRestart state{adr.iterations(), reference, broken_start, adr.velocity(), adr.previous_force()};
      gather_particle_values(part, model.particles.dim, state.v, PETSC_COMM_WORLD);
      gather_particle_values(part, model.particles.dim, state.f_prev, PETSC_COMM_WORLD);
      if (root) run.save_checkpoint(s, relaxation_scalars(state));
    }
    progress.update(s, s, fmt::format(", |r|/ref = {:.3e}", ratio));
  }
  steps.gather();
  rep.last_step = s;
  rep.time = s;
  rep.converged = ratio <= dyn.tolerance;
  rep.residual_ratio = ratio;
  rep.damping = adr.damping();
  rep.strain_available = model.assembler->has_energy();
  if (rep.strain_available && root) rep.strain = model.assembler->strain_energy(u.data());
  run.summary.newton.converged = rep.converged;
  run.log(fmt::format("  relaxation: {} after {} iterations, |r|/ref = {:.3e}", rep.converged ? "converged" : "not converged", s, ratio));
  RunSummary summary = run.summary;
  if (root) {
    summary = run.finish(broken_start, t0, write);
  } else {
    summary.solve_seconds = seconds_since(t0);
  }
  if (!rep.converged && stop_after == 0)
    throw std::runtime_error(fmt::format("adaptive dynamic relaxation did not converge in {} iterations (|r|/ref = {:.3e} > {:.3g})", s,
                                         ratio, dyn.tolerance));
  return summary;
}

}  // namespace pd
