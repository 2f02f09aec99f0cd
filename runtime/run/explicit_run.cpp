// Explicit dynamics: velocity Verlet from t = 0 (or a checkpoint) to the last step.
#include "run/dynamic_run.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "damage/critical_stretch.hpp"
#include "dynamics/energies.hpp"
#include "dynamics/progress.hpp"
#include "dynamics/verlet_integrator.hpp"
#include "interrupt.hpp"
#include "run/run_outputs.hpp"
#include "solve/stopwatch.hpp"

namespace pd {

RunSummary run_explicit(DynamicRun& run, bool write, int stop_after) {
  const Scene& scene = run.scene;
  Model& model = run.model;
  RunSummary& summary = run.summary;
  std::vector<double>& u = run.u;
  const DynamicRun::Log& log = run.log;
  const double dt = run.dt();
  const auto t0 = std::chrono::steady_clock::now();
  const DynamicsSpec& dyn = *scene.dynamics;
  DynamicsReport& rep = run.start_report();
  rep.dt = dt, rep.dt_stable = model.inertia->dt_stable, rep.damping = dyn.damping;
  rep.dt_rule = dyn.dt > 0 ? "fixed" : fmt::format("{} x the stable estimate", dyn.safety_factor);
  ExternalWork work;
  int step = 0;
  long long broken_start = broken_bond_count(model.bonds);
  std::vector<double> scalars;
  if (!dyn.restart.empty()) {
    run.restore(dyn.restart, step, scalars);
    if (scalars.size() < 2) throw std::runtime_error(dyn.restart + ": the checkpoint has no energy accumulators");
    work.restore(scalars[0]);
    broken_start = static_cast<long long>(scalars[1]);
  } else {
    run.apply_initial_conditions();
    run.prescribe(0.0);
    run.after_step();
  }
  rep.first_step = step;
  const int last = stop_after > 0 ? std::min(stop_after, dyn.steps) : dyn.steps;
  const VerletIntegrator verlet(*model.inertia, model.damping, model.dofs.free_dofs(), dt);
  std::vector<double> f, g, f_old, g_old, u_old;
  double t = step * dt;
  run.forces(t, f, g);
  auto record = [&](int s) {
    SeriesRow r = run.make_row(s, t, 0.0);
    r.external_work = work.value();
    run.series.push_back(r);
  };
  if (step == 0) {
    record(0);
    if (dyn.snapshot_every > 0 && write) run.write_snapshot(0, 0.0);
  }
  Progress progress(log, write ? dyn.progress_seconds : 0.0, step, last);
  for (int s = step + 1; s <= last; ++s) {
    if (interrupt_signal() != 0) throw_if_interrupted(fmt::format("at time step {} of {}", s, last));
    u_old = u;
    g_old = g;
    verlet.first_half(u, run.v, f);
    t = s * dt;
    run.prescribe(t);
    run.after_step();
    run.forces(t, f, g);
    verlet.second_half(run.v, f);
    work.add(g_old, g, u_old, u);
    if (s % dyn.output_every == 0 || s == dyn.steps) record(s);
    if (write && dyn.snapshot_every > 0 && (s % dyn.snapshot_every == 0 || s == dyn.steps)) run.write_snapshot(s, t);
    if (dyn.checkpoint_every > 0 && s % dyn.checkpoint_every == 0) run.save_checkpoint(s, {work.value(), static_cast<double>(broken_start)});
    progress.update(s, t);
  }
  for (double x : u)
    if (!std::isfinite(x)) throw std::runtime_error(fmt::format("the displacement is not finite (unstable time step? dt = {:.6g})", dt));
  rep.last_step = last;
  rep.time = last * dt;
  const SeriesRow end = run.make_row(last, rep.time, 0.0);
  rep.kinetic = end.kinetic;
  rep.strain_available = model.assembler->has_energy();
  rep.strain = end.strain;
  rep.external_work = work.value();
  rep.bonds_broken = broken_bond_count(model.bonds) - broken_start;
  summary.broken_bonds = static_cast<int>(broken_bond_count(model.bonds));
  const std::vector<double> stress = run.stress_field();
  summary.probes = evaluate_probes(scene, model.particles, run.probe_ids, u, &stress);
  summary.solve_seconds = seconds_since(t0);
  if (write) run.write_results();
  log(summary.text());
  return summary;
}


}  // namespace pd
