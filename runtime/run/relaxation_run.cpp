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
  Model& model = run.model;
  RunSummary& summary = run.summary;
  std::vector<double>& u = run.u;
  const DynamicRun::Log& log = run.log;
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
  // Checkpoint scalars: [iterations, reference, broken_start, v (N), f_prev (N)]. The
  // reference is the one of iteration 0: recomputed at the restored u it would be the
  // residual there, and the restarted run would stop at another iteration.
  constexpr std::size_t kHead = 3;
  if (!dyn.restart.empty()) {
    std::vector<double> scalars;
    run.restore(dyn.restart, step, scalars);
    const std::size_t N = u.size();
    if (scalars.size() != kHead + 2 * N) throw std::runtime_error(dyn.restart + ": not a relaxation checkpoint of this scene");
    const auto v_begin = scalars.begin() + kHead, f_begin = v_begin + static_cast<std::ptrdiff_t>(N);
    adr.restore(static_cast<int>(scalars[0]), std::vector<double>(v_begin, f_begin), std::vector<double>(f_begin, scalars.end()));
    reference = scalars[1];
    broken_start = static_cast<long long>(scalars[2]);
    run.forces(0.0, f, g);
  } else {
    run.apply_initial_conditions();
    run.prescribe(0.0);
    run.forces(0.0, f, g);
    // The reference force: the larger of the loads and the initial out-of-balance force.
    reference = norm_over(f, model.dofs.free_dofs());
    for (const auto& e : model.effects) {
      if (!e->is_load()) continue;
      std::vector<double> load(u.size(), 0.0);
      e->add_forces(u.data(), 0.0, load.data());  // in full: relaxation has no time functions
      reference = std::max(reference, norm_over(load, model.dofs.free_dofs()));
    }
    if (reference == 0) reference = 1;
  }
  rep.first_step = step;
  const int last = stop_after > 0 ? std::min(stop_after, dyn.steps) : dyn.steps;
  double ratio = norm_over(f, model.dofs.free_dofs()) / reference;
  if (step == 0) run.series.push_back(run.make_row(0, 0, ratio));
  Progress progress(log, write ? dyn.progress_seconds : 0.0, step, last);
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
      std::vector<double> scalars{static_cast<double>(adr.iterations()), reference, static_cast<double>(broken_start)};
      scalars.insert(scalars.end(), adr.velocity().begin(), adr.velocity().end());
      scalars.insert(scalars.end(), adr.previous_force().begin(), adr.previous_force().end());
      run.save_checkpoint(s, scalars);
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
  rep.bonds_broken = broken_bond_count(model.bonds) - broken_start;
  summary.broken_bonds = static_cast<int>(broken_bond_count(model.bonds));
  summary.newton.converged = rep.converged;
  const std::vector<double> stress = run.stress_field();
  summary.probes = evaluate_probes(scene, model.particles, run.probe_ids, u, &stress);
  summary.solve_seconds = seconds_since(t0);
  log(fmt::format("  relaxation: {} after {} iterations, |r|/ref = {:.3e}", rep.converged ? "converged" : "not converged", s, ratio));
  if (write) run.write_results();
  log(summary.text());
  if (!rep.converged && stop_after == 0)
    throw std::runtime_error(fmt::format("adaptive dynamic relaxation did not converge in {} iterations (|r|/ref = {:.3e} > {:.3g})", s,
                                         ratio, dyn.tolerance));
  return summary;
}


}  // namespace pd
