// run_static: Newton over the load steps on the model's system, then what the answer reports.
#include "run/static_run.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <span>
#include <stdexcept>

#include "constraints/constraints.hpp"
#include "damage/critical_stretch.hpp"
#include "effects/loads.hpp"
#include "input/yaml_keys.hpp"
#include "post/smoothing.hpp"
#include "post/stability_warning.hpp"
#include "run/peridynamic_system.hpp"
#include "run/run_outputs.hpp"
#include "solve/distributed_backend.hpp"
#include "stopwatch.hpp"

namespace pd {

namespace {
NewtonSettings newton_settings(const SolverSpec& sv, const SolverPlan& plan) {
  NewtonSettings s;
  s.load_steps = sv.load_steps;
  s.load_path = sv.load_path;
  s.duration = sv.duration;
  s.max_iterations = sv.max_iterations;
  s.max_step_cuts = sv.max_step_cuts;
  s.relative_tolerance = sv.tolerance;
  s.increment_tolerance = sv.increment_tolerance;
  s.matrix_free = plan.matrix_free();
  s.matrix_free_preconditioner = plan.short_horizon_preconditioner()
                                     ? MatrixFreePreconditioner::approximate_tangent
                                     : MatrixFreePreconditioner::jacobi;
  s.linear.method = s.matrix_free ? LinearMethod::automatic : plan.linear;
  s.linear.preconditioner = plan.preconditioner;
  s.linear.tolerance = sv.krylov_tolerance;
  s.linear.max_iterations = sv.krylov_max_iterations;
  s.linear.direct_max_nonzeros = sv.direct_max_nonzeros;
  s.krylov_tolerance = sv.krylov_tolerance;
  if (sv.krylov_max_iterations > 0)
    s.krylov_max_iterations = sv.krylov_max_iterations;
  else
    s.krylov_max_iterations = 20000;
  return s;
}

// No load at all: the solution is zero, and Newton would only chase the residual's
// rounding noise. A load that falls entirely on prescribed components (a traction on
// fixed particles) is taken by the constraints and does no work: warned, and no load.
bool has_load(StaticRun& run, const Model& model, const Scene& scene, const RunLog& log) {
  const DofMap& dofs = model.dofs;
  const auto free_force = [&](const Effect& e) {
    std::vector<double> zero(run.u.size(), 0.0), force(run.u.size(), 0.0);
    e.add_forces(zero.data(), 1.0, force.data());
    return dofs
        .restrict_free(
            Eigen::Map<const Eigen::VectorXd>(force.data(), static_cast<Eigen::Index>(force.size())))
        .norm();
  };
  for (const BoundaryCondition& bc : scene.boundary) {
    if (bc.kind != BoundaryCondition::Kind::Traction && bc.kind != BoundaryCondition::Kind::BodyForce)
      continue;
    if (bc.method == BoundaryCondition::Method::fictitious_layer)
      continue;  // a load through the layer's ties
    if (free_force(*make_external_loads(scene, model.particles, std::span(&bc, 1))) > 0.0) continue;
    const std::string w =
        bc.where + ": the " + (bc.kind == BoundaryCondition::Kind::Traction ? "traction" : "body force") +
        " acts only on components whose displacement is prescribed: the constraints take it and it "
        "does no work (check the regions)";
    run.summary.warnings.push_back(w);
    log("  warning: " + w);
  }
  bool loaded = false;
  for (double v : dofs.prescribed()) loaded = loaded || v != 0.0;
  for (const TiedDof& t : dofs.ties()) loaded = loaded || t.offset != 0.0;
  for (const auto& e : model.effects) loaded = loaded || free_force(*e) > 0.0;
  if (!loaded) log("  no load on a free component and no prescribed displacement: the solution is zero");
  return loaded;
}

// A standing load step's probes (StaticRun::load_step_rows), with several steps and probes.
// Evaluated after the history commit, as the final probes are.
void record_load_step(StaticRun& run, const Model& model, const Scene& scene, int step, double load,
                      const Eigen::VectorXd& u) {
  if (scene.solver.load_steps < 2 || scene.probes.empty()) return;
  const std::vector<double> at(u.data(), u.data() + u.size());
  const std::vector<double> stress =
      wants_stress(scene) ? model.assembler->stresses(at.data()) : std::vector<double>{};
  StaticRun::LoadStepRow row{step, load, run.time, {}};
  for (const ProbeResult& p :
       evaluate_probes(scene, model.particles, probe_particles(scene, model.particles), at, &stress))
    row.probes.push_back(p.value);
  run.load_step_rows.push_back(std::move(row));
}

// After a converged load step every effect may change the model (damage evolution
// breaks bonds and updates the moments: effects/damage_evolution.cpp); any change
// means the step is solved again on the changed system. A step that stands commits the
// law's history (a law with memory): only converged, final states reach it.
long long after_load_step(StaticRun& run, Model& model, const Scene& scene, const RunLog& log, int step,
                          double load, const Eigen::VectorXd& u) {
  long long changes = 0;
  for (const auto& e : model.effects) changes += e->after_step(u.data(), FamilyScope{});
  if (changes == 0) {
    model.commit_history(u.data());
    // The committed state is the converged one: read at a zero duration it gives the forces
    // Newton converged on (a rate-dependent law would otherwise relax one more step in the
    // probes and outputs). The next increment sets its own duration.
    model.step_duration = 0.0;
    record_load_step(run, model, scene, step, load, u);
    return 0;
  }
  log(fmt::format("  load {:.3g} (step {}/{}): {} bonds broke ({} broken in all); solving the step again",
                  load, step, scene.solver.load_steps, changes, broken_bond_count(model.bonds)));
  // A piece cut loose by the new crack faces would make K singular: say which.
  check_held(model.particles, model.bonds, model.dofs);
  return changes;
}

// output.smoothing (paper 000 eq. 49): u_s, the relative oscillation and eq. 48 for u_s.
void smooth(StaticRun& run, const Model& model, const Scene& scene, const RunLog& log) {
  const abi::InfluenceDescriptor* w = abi::find_influence(scene.output.smoothing_influence);
  const std::vector<double>& u = run.u;
  run.u_smooth = smooth_field(model.particles, model.bonds, w->weight, u, model.particles.dim);
  double num = 0, den = 0;
  for (std::size_t i = 0; i < u.size(); ++i) num += std::pow(u[i] - run.u_smooth[i], 2), den += u[i] * u[i];
  run.summary.smoothing = w->name;
  run.summary.oscillation = den > 0 ? std::sqrt(num / den) : 0.0;
  log(fmt::format("  smoothing (paper 000 eq. 49, influence {}): |u - u_s| / |u| = {:.6e}", w->name,
                  run.summary.oscillation));
  if (scene.reference) {
    run.summary.smoothed_field_error = field_error(scene, *scene.reference, model.particles, run.u_smooth);
    log(fmt::format("  field error of the smoothed solution (eq. 48): {:.6e}",
                    run.summary.smoothed_field_error));
  }
}

// Probes, eq. 48, smoothing and J-integrals of the answer run.u.
void report(StaticRun& run, const Model& model, const Scene& scene, const RunLog& log) {
  RunSummary& summary = run.summary;
  const std::vector<double>& u = run.u;
  if (wants_stress(scene)) run.stress = model.assembler->stresses(u.data());
  summary.probes =
      evaluate_probes(scene, model.particles, probe_particles(scene, model.particles), u, &run.stress);
  log_zero_energy_content(model.particles, model.bonds, u, summary.law, log);
  if (scene.reference) {
    summary.has_field_error = true;
    summary.field_error = field_error(scene, *scene.reference, model.particles, u);
    log(fmt::format("  field error against {} (paper 000 eq. 48): {:.6e}", scene.reference->solution,
                    summary.field_error));
    summary.rms_error =
        rms_error_free(scene, *scene.reference, model.particles, model.dofs, u, summary.rms_particles);
    log(fmt::format("  RMS error over the {} free particles (paper 001 §4): {:.6e}", summary.rms_particles,
                    summary.rms_error));
  }
  if (!scene.output.smoothing_influence.empty()) smooth(run, model, scene, log);
  std::vector<double> external(scene.output.j_integral.empty() ? 0 : u.size(), 0.0);
  for (const auto& e : model.effects)
    if (!external.empty()) e->add_forces(u.data(), 1.0, external.data());
  for (const JContour& c : scene.output.j_integral) {
    summary.j_integrals.push_back(
        j_integral(bond_families(*model.assembler, "the J-integral"), u.data(), scene.h, c, external.data()));
    log(j_integral_line(summary.j_integrals.back()));
  }
  for (const auto& p : summary.probes) log(probe_log_line(p));
}
}  // namespace

void run_static(StaticRun& run, Model& model, const Scene& scene, const RunLog& log) {
  const auto t0 = std::chrono::steady_clock::now();
  RunSummary& summary = run.summary;
  const DofMap& dofs = model.dofs;
  check_scene_holds_body(scene, model.particles, model.bonds, dofs);
  const bool loaded = has_load(run, model, scene, log);

  std::vector<const Effect*> effects;
  for (const auto& e : model.effects) effects.push_back(e.get());
  PeridynamicSystem system(*model.assembler, effects, model.approximation.get());
  Eigen::VectorXd u = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(run.u.size()));
  const long long broken_before = broken_bond_count(model.bonds);
  if (loaded) {
    NewtonSettings settings = newton_settings(scene.solver, run.plan);
    settings.after_step = [&](int step, double load, const Eigen::VectorXd& v) {
      return after_load_step(run, model, scene, log, step, load, v);
    };
    if (scene.damage) settings.max_resolves = scene.damage->max_resolves;
    // A rate-dependent law integrates its update over each increment's physical duration.
    settings.begin_increment = [&](double t_start, double t_end) {
      model.step_duration = t_end - t_start;
      run.time = t_end;
    };
    if (run.plan.backend == Backend::petsc) {
      if (dofs.tied_count() > 0)
        throw SceneError(scene.file +
                         ": solver.backend: the PETSc backend does not take fictitious layers "
                         "(multipoint constraints); use the serial backend");
      const FamilyAssembler& tangent = bond_families(*model.assembler, "backend petsc");
      const FamilyAssembler& pc =
          model.approximation ? bond_families(*model.approximation, "backend petsc") : tangent;
      summary.newton =
          solve_distributed({&tangent, &pc, effects, &dofs, system.symmetric(), settings}, u, log);
    } else {
      summary.newton = NewtonSolver(settings, log).solve(system, dofs, u);
    }
  } else {
    summary.newton.converged = true;
    summary.newton.unknowns = dofs.free_count();
  }
  summary.solve_seconds = seconds_since(t0);
  if (model.damage) {
    summary.bonds_broken_by_damage = broken_bond_count(model.bonds) - broken_before;
    summary.broken_bonds = static_cast<int>(broken_bond_count(model.bonds));
  }
  if (!summary.newton.linear_choice.empty())
    log(fmt::format("  linear solver: {} ({})", summary.newton.linear_solver, summary.newton.linear_choice));
  if (!summary.newton.converged) throw std::runtime_error(summary.newton.message);
  for (Eigen::Index i = 0; i < u.size(); ++i)
    if (!std::isfinite(u[i]))
      throw std::runtime_error(fmt::format("the solution is not finite at particle {} (law {})",
                                           i / model.particles.dim, summary.law));
  run.u.assign(u.data(), u.data() + u.size());
  report(run, model, scene, log);
}

}  // namespace pd
