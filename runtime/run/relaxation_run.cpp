// Adaptive dynamic relaxation to the static answer.
#include "run/dynamic_run.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "damage/critical_stretch.hpp"
#include "dynamics/dynamic_relaxation.hpp"
#include "dynamics/progress.hpp"
#include "effects/inertia.hpp"
#include "interrupt.hpp"
#include "run/constraints.hpp"
#include "run/relaxation_state.hpp"
#include "run/run_outputs.hpp"
#include "solve/stopwatch.hpp"

namespace pd {

namespace {
double norm_over(const std::vector<double>& v, const std::vector<int>& dofs) {
  double s = 0;
  for (int i : dofs) s += v[i] * v[i];
  return std::sqrt(s);
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
  AdaptiveDynamicRelaxation adr(model.inertia->mass(), model.dofs.free_dofs());
  int step = 0;
  long long broken_start = broken_bond_count(model.bonds);
  std::vector<double> f, g;
  double reference = 0;
  if (!dyn.restart.empty()) {
    std::vector<double> scalars;
    run.restore(dyn.restart, step, scalars);
    RelaxationRestart state = relaxation_restart(scalars, u.size(), dyn.restart);
    adr.restore(state.iterations, std::move(state.v), std::move(state.f_prev));
    reference = state.reference;
    broken_start = state.broken_start;
    run.forces(0.0, f, g);
  } else {
    run.apply_initial_conditions();
    run.prescribe(0.0);
    run.forces(0.0, f, g);
    reference = relaxation_reference(model, u, f, [&](const std::vector<double>& v) { return norm_over(v, model.dofs.free_dofs()); });
  }
  rep.first_step = step;
  const int last = stop_after > 0 ? std::min(stop_after, dyn.steps) : dyn.steps;
  double ratio = norm_over(f, model.dofs.free_dofs()) / reference;
  if (step == 0) run.series.push_back(run.make_row(0, 0, ratio));
  Progress progress(run.log, write ? dyn.progress_seconds : 0.0, step, last);
  int s = step;
  while (ratio > dyn.tolerance && s < last) {
    if (interrupt_signal() != 0) throw_if_interrupted(fmt::format("at relaxation iteration {} of at most {}", s + 1, last));
    ++s;
    adr.step(f, u);
    model.dofs.apply_ties(u.data(), 1.0);  // a fictitious layer follows the body's update
    run.after_step();
    run.forces(0.0, f, g);
    ratio = norm_over(f, model.dofs.free_dofs()) / reference;
    if (!std::isfinite(ratio)) throw std::runtime_error(fmt::format("adaptive dynamic relaxation diverged at iteration {}", s));
    const bool done = ratio <= dyn.tolerance;
    if (s % dyn.output_every == 0 || done) run.series.push_back(run.make_row(s, s, ratio));
    if (write && dyn.snapshot_every > 0 && (s % dyn.snapshot_every == 0 || done)) run.write_snapshot(s, s);
    if (dyn.checkpoint_every > 0 && s % dyn.checkpoint_every == 0) {
      run.save_checkpoint(s, relaxation_scalars({adr.iterations(), reference, broken_start, adr.velocity(), adr.previous_force()}));
    }
    progress.update(s, s, fmt::format(", |r|/ref = {:.3e}", ratio));
  }
  rep.last_step = s;
  rep.time = s;
  rep.converged = ratio <= dyn.tolerance;
  rep.residual_ratio = ratio;
  rep.damping = adr.damping();
  rep.strain_available = model.assembler->has_energy();
  if (rep.strain_available) rep.strain = model.assembler->strain_energy(u.data());
  run.summary.newton.converged = rep.converged;
  run.log(fmt::format("  relaxation: {} after {} iterations, |r|/ref = {:.3e}", rep.converged ? "converged" : "not converged", s, ratio));
  RunSummary summary = run.finish(broken_start, t0, write);
  if (!rep.converged && stop_after == 0)
    throw std::runtime_error(fmt::format("adaptive dynamic relaxation did not converge in {} iterations (|r|/ref = {:.3e} > {:.3g})", s,
                                         ratio, dyn.tolerance));
  return summary;
}

}  // namespace pd
