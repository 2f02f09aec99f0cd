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
#include <petscvec.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "damage/critical_stretch.hpp"
#include "dynamics/energies.hpp"
#include "dynamics/progress.hpp"
#include "dynamics/verlet_integrator.hpp"
#include "interrupt.hpp"
#include "petsc/distributed_body.hpp"
#include "petsc/distributed_dynamics.hpp"
#include "petsc/petsc_check.hpp"
#include "petsc/rank_gather.hpp"
#include "run/dynamic_run.hpp"
#include "run/run_outputs.hpp"
#include "solve/stopwatch.hpp"

namespace pd {

namespace {

class DistributedExplicit {
 public:
  explicit DistributedExplicit(DynamicRun& run)
      : s_(run), body_(run.model.particles, run.model.bonds, PETSC_COMM_WORLD), part_(body_.partition()) {
    const int d = s_.model.particles.dim;
    std::vector<char> constrained(s_.u.size(), 0);
    for (int i : s_.model.dofs.constrained_dofs()) constrained[i] = 1;
    for (int i = 0; i < part_.owned(); ++i) {
      const int p = part_.owned_particle(i);
      owned_families_.push_back(p);
      for (int c = 0; c < d; ++c) {
        const int dof = p * d + c;
        owned_dofs_.push_back(dof);
        (constrained[dof] ? owned_constrained_ : owned_free_).push_back(dof);
      }
    }
    // Every dof a rank may hold besides its own: what the work's load vector must not count.
    std::vector<char> owned(s_.u.size(), 0);
    for (int dof : owned_dofs_) owned[dof] = 1;
    for (std::size_t i = 0; i < owned.size(); ++i)
      if (!owned[i]) foreign_dofs_.push_back(static_cast<int>(i));
    if (s_.model.damage)
      damage_.emplace(s_.model.particles, s_.model.bonds, s_.model.damage->s0(), s_.model.damage->tension_only());
    x_ = body_.create_vector();
    F_ = body_.create_vector();
  }
  ~DistributedExplicit() {
    VecDestroy(&x_);
    VecDestroy(&F_);
  }
  DistributedExplicit(const DistributedExplicit&) = delete;
  DistributedExplicit& operator=(const DistributedExplicit&) = delete;

  RunSummary run(bool write, int stop_after);

 private:
  void ghost_update();
  void forces(double t, std::vector<double>& f, std::vector<double>& g);
  bool break_bonds();
  void gather();
  double global_sum(double local) const {
    double global = 0;
    MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
    return global;
  }

  DynamicRun& s_;
  DistributedBody body_;
  const Partition& part_;
  std::vector<int> owned_families_, owned_dofs_, owned_free_, owned_constrained_, foreign_dofs_;
  std::optional<CriticalStretchDamage> damage_;
  Vec x_ = nullptr, F_ = nullptr;
  std::vector<double> f_local_;
};

// u at the ghosts = their owners' u (the owned entries are the rank's own already).
void DistributedExplicit::ghost_update() {
  PetscScalar* a;
  check(VecGetArray(x_, &a), "VecGetArray");
  for (std::size_t k = 0; k < owned_dofs_.size(); ++k) a[k] = s_.u[owned_dofs_[k]];
  check(VecRestoreArray(x_, &a), "VecRestoreArray");
  body_.to_local(x_, s_.u);
}

// The serial driver's forces() at the owned dofs: f = f_int + loads(t); g = the loads on
// free dofs and -f_int on constrained ones (the reactions' work), zero at foreign dofs.
void DistributedExplicit::forces(double t, std::vector<double>& f, std::vector<double>& g) {
  f.resize(s_.u.size());
  g.assign(s_.u.size(), 0.0);
  body_.internal_forces(*s_.model.assembler, s_.u, f_local_);
  body_.from_local(f_local_, F_);
  const PetscScalar* a;
  check(VecGetArrayRead(F_, &a), "VecGetArrayRead");
  for (std::size_t k = 0; k < owned_dofs_.size(); ++k) f[owned_dofs_[k]] = a[k];
  check(VecRestoreArrayRead(F_, &a), "VecRestoreArrayRead");
  for (const auto& e : s_.model.effects) e->add_forces(s_.u.data(), t, g.data());
  for (int i : foreign_dofs_) g[i] = 0.0;
  for (int i : owned_dofs_) f[i] += g[i];
  for (int i : owned_constrained_) g[i] = g[i] - f[i];
}

// The damage effect's after_step on the rank's own families (the serial after_step
// would read u at particles this rank does not hold). Moments follow the broken bonds.
bool DistributedExplicit::break_bonds() {
  if (!damage_ || damage_->break_family_bonds(s_.u.data(), owned_families_) == 0) return false;
  s_.model.assembler->update_moments();
  return true;
}

// Rank 0's u, v and alpha = the owners' (for a row, snapshot, checkpoint or the end).
void DistributedExplicit::gather() {
  const int d = s_.model.particles.dim;
  gather_particle_values(part_, d, s_.u, PETSC_COMM_WORLD);
  gather_particle_values(part_, d, s_.v, PETSC_COMM_WORLD);
  if (!s_.model.assembler->intact()) {
    gather_family_alpha(part_, s_.model.bonds, PETSC_COMM_WORLD);
    // Rank 0's other families now have their owners' broken bonds: their moments too
    // (the strain energy of a series row reads every family's).
    if (part_.rank == 0) s_.model.assembler->update_moments();
  }
}

RunSummary DistributedExplicit::run(bool write, int stop_after) {
  const auto t0 = std::chrono::steady_clock::now();
  RunSummary& summary = s_.summary;
  DynamicsReport& rep = s_.start_report();
  const DynamicsSpec& dyn = *s_.scene.dynamics;
  if (dyn.method != DynamicsMethod::explicit_verlet)
    throw std::runtime_error("solver.backend: petsc runs explicit dynamics only; dynamic relaxation is serial (or solve "
                             "the static scene with the PETSc backend)");
  const bool root = part_.rank == 0;
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
  const VerletIntegrator verlet(*s_.model.inertia, s_.model.damping, owned_free_, dt);
  std::vector<double> f, g, g_old, u_old;
  double t = step * dt;
  forces(t, f, g);
  auto record = [&](int st) {
    const double w = global_sum(work.value());
    if (!root) return;
    SeriesRow r = s_.make_row(st, t, 0.0);
    r.external_work = w;
    s_.series.push_back(r);
  };
  if (step == 0) {
    gather();
    record(0);
    if (dyn.snapshot_every > 0 && write) s_.write_snapshot(0, 0.0);
  }
  Progress progress(s_.log, write ? dyn.progress_seconds : 0.0, step, last);
  for (int st = step + 1; st <= last; ++st) {
    // A signal reaches the ranks at different moments: they agree on it every step
    // (one integer all-reduce), so all stop at the same step instead of one rank leaving
    // the others waiting in the next ghost update.
    int local_signal = interrupt_signal(), signal = 0;
    MPI_Allreduce(&local_signal, &signal, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
    if (signal != 0) {
      if (local_signal == 0) request_interrupt(signal);
      throw_if_interrupted(fmt::format("at time step {} of {}", st, last));
    }
    u_old = s_.u;
    g_old = g;
    verlet.first_half(s_.u, s_.v, f);
    t = st * dt;
    s_.prescribe(t);
    ghost_update();
    break_bonds();
    forces(t, f, g);
    verlet.second_half(s_.v, f);
    work.add(g_old, g, u_old, s_.u);
    const bool row = st % dyn.output_every == 0 || st == dyn.steps;
    const bool snapshot = dyn.snapshot_every > 0 && (st % dyn.snapshot_every == 0 || st == dyn.steps);
    const bool checkpoint = dyn.checkpoint_every > 0 && st % dyn.checkpoint_every == 0;
    if (row || snapshot || checkpoint) gather();
    if (row) record(st);
    if (write && snapshot) s_.write_snapshot(st, t);
    if (checkpoint) {
      const double w = global_sum(work.value());
      if (root) s_.save_checkpoint(st, {w, static_cast<double>(broken_start)});
    }
    progress.update(st, t);
  }
  gather();
  int finite = 1, all_finite = 0;
  for (int i : owned_dofs_) finite = finite && std::isfinite(s_.u[i]);
  MPI_Allreduce(&finite, &all_finite, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD);
  if (!all_finite)
    throw std::runtime_error(fmt::format("the displacement is not finite (unstable time step? dt = {:.6g})", dt));
  const double total_work = global_sum(work.value());
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

RunSummary run_distributed_dynamics(DynamicRun& run, bool write, int stop_after) {
  DistributedExplicit distributed(run);
  return distributed.run(write, stop_after);
}

}  // namespace pd
