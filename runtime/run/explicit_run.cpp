// Explicit dynamics: velocity Verlet from t = 0 (or a checkpoint) to the last step.
#include "run/dynamic_simulation.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>

#include "discretize/discretization.hpp"
#include "discretize/family_quality.hpp"
#include "model/model.hpp"
#include "dynamics/checkpoint.hpp"
#include "dynamics/dynamic_relaxation.hpp"
#include "dynamics/energies.hpp"
#include "dynamics/progress.hpp"
#include "dynamics/pvd_writer.hpp"
#include "dynamics/time_step.hpp"
#include "dynamics/verlet_integrator.hpp"
#include "fields/analytic.hpp"
#include "input/yaml_keys.hpp"
#include "interrupt.hpp"
#include "output/atomic_file.hpp"
#include "output/csv_writer.hpp"
#include "output/vtu_writer.hpp"
#include "run/constraints.hpp"
#include "run/run_outputs.hpp"
#include "solve/stopwatch.hpp"

namespace pd {

RunSummary DynamicSimulation::run_explicit(bool write, int stop_after) {
  const auto t0 = std::chrono::steady_clock::now();
  const DynamicsSpec& dyn = *scene_.dynamics;
  DynamicsReport& rep = *summary_.dynamics;
  rep.dt = dt_, rep.dt_stable = dt_stable_, rep.damping = dyn.damping;
  rep.dt_rule = dyn.dt > 0 ? "fixed" : fmt::format("{} x the stable estimate", dyn.safety_factor);
  ExternalWork work;
  int step = 0;
  long long broken_start = broken_bond_count(model_.bonds);
  std::vector<double> scalars;
  if (!dyn.restart.empty()) {
    restore(dyn.restart, step, scalars);
    if (scalars.size() < 2) throw std::runtime_error(dyn.restart + ": the checkpoint has no energy accumulators");
    work.restore(scalars[0]);
    broken_start = static_cast<long long>(scalars[1]);
  } else {
    apply_initial_conditions();
    prescribe(0.0);
    after_step();
  }
  rep.first_step = step;
  const int last = stop_after > 0 ? std::min(stop_after, dyn.steps) : dyn.steps;
  const VerletIntegrator verlet(
      [&] {
        std::vector<double> inv(mass_.size());
        for (std::size_t i = 0; i < mass_.size(); ++i) inv[i] = 1.0 / mass_[i];
        return inv;
      }(),
      free_, dt_, dyn.damping);
  std::vector<double> f, g, f_old, g_old, u_old;
  double t = step * dt_;
  forces(t, f, g);
  auto record = [&](int s) {
    SeriesRow r = make_row(s, t, 0.0);
    r.external_work = work.value();
    series_.push_back(r);
  };
  if (step == 0) {
    record(0);
    if (dyn.snapshot_every > 0 && write) write_snapshot(0, 0.0);
  }
  Progress progress(log_, write ? dyn.progress_seconds : 0.0, step, last);
  for (int s = step + 1; s <= last; ++s) {
    if (interrupt_signal() != 0) throw_if_interrupted(fmt::format("at time step {} of {}", s, last));
    u_old = u_;
    g_old = g;
    verlet.first_half(u_, v_, f);
    t = s * dt_;
    prescribe(t);
    after_step();
    forces(t, f, g);
    verlet.second_half(v_, f);
    work.add(g_old, g, u_old, u_);
    if (s % dyn.output_every == 0 || s == dyn.steps) record(s);
    if (write && dyn.snapshot_every > 0 && (s % dyn.snapshot_every == 0 || s == dyn.steps)) write_snapshot(s, t);
    if (dyn.checkpoint_every > 0 && s % dyn.checkpoint_every == 0) save_checkpoint(s, {work.value(), static_cast<double>(broken_start)});
    progress.update(s, t);
  }
  for (double x : u_)
    if (!std::isfinite(x)) throw std::runtime_error(fmt::format("the displacement is not finite (unstable time step? dt = {:.6g})", dt_));
  rep.last_step = last;
  rep.time = last * dt_;
  const SeriesRow end = make_row(last, rep.time, 0.0);
  rep.kinetic = end.kinetic;
  rep.strain_available = model_.assembler->has_energy();
  rep.strain = end.strain;
  rep.external_work = work.value();
  rep.bonds_broken = broken_bond_count(model_.bonds) - broken_start;
  summary_.broken_bonds = static_cast<int>(broken_bond_count(model_.bonds));
  const std::vector<double> stress = stress_field();
  summary_.probes = evaluate_probes(scene_, model_.particles, probe_ids_, u_, &stress);
  summary_.solve_seconds = seconds_since(t0);
  if (write) write_results();
  log_(summary_.text());
  return summary_;
}


}  // namespace pd
