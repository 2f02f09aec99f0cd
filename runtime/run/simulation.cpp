// The static run driver.
#include "run/simulation.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <span>
#include <stdexcept>

#include "discretize/discretization.hpp"
#include "discretize/family_quality.hpp"
#include "assembly/strain_modes.hpp"
#include "fields/analytic.hpp"
#include "input/yaml_keys.hpp"
#include "interrupt.hpp"
#include "output/atomic_file.hpp"
#include "output/csv_writer.hpp"
#include "output/vtu_writer.hpp"
#include "damage/critical_stretch.hpp"
#include "post/peridynamic_stress.hpp"
#include "post/smoothing.hpp"
#include "post/stability_warning.hpp"
#include "model/model.hpp"
#include "run/constraints.hpp"
#include "run/peridynamic_system.hpp"
#include "run/run_outputs.hpp"
#include "solve/distributed_backend.hpp"
#include "solve/stopwatch.hpp"
#include "solve/solver_plan.hpp"

namespace pd {

Simulation::~Simulation() = default;

Simulation::Simulation(Scene scene, Log log) : scene_(std::move(scene)), log_(std::move(log)) {
  const auto t0 = std::chrono::steady_clock::now();
  model_ = build_model(scene_);
  summary_.describe(scene_, model_);
  const abi::LawDescriptor* law = model_.law;
  const abi::InfluenceDescriptor* influence = model_.influence;
  const FamilyQualityReport& quality = model_.quality;
  // Simulate only what the scene calls for: no broken bond -> the variant without alpha;
  // matrix-free Newton-Krylov -> no sparsity pattern and no slot table.
  const double short_delta = std::min(scene_.delta(), scene_.solver.preconditioner_ratio * scene_.h);
  // Only `auto` sizes the preconditioner before choosing (a pass over every bond).
  const double short_family =
      plan_needs_short_family_size(scene_.solver) ? mean_short_family_size(model_.bonds, short_delta, influence->weight) : -1;
  plan_ = plan_solver(scene_.solver, model_.size(scene_, short_family));
  summary_.solver_path = plan_.reason;
  // PETSc with delta <= ratio h: its preconditioning matrix is the tangent's own.
  if (plan_.short_horizon_preconditioner() && !(plan_.backend == Backend::petsc && short_delta >= scene_.delta()))
    attach_short_horizon(model_, scene_, short_delta);
  const AssemblerOptions options = attach_assembler(model_, scene_, !plan_.matrix_free());
  attach_effects(model_, scene_);
  if (model_.collocation) summary_.effects.push_back(model_.collocation_description);
  if (model_.gauss_points) summary_.effects.push_back(model_.gauss_points->describe());
  const StrainModeReport modes = check_strain_modes(*model_.assembler, influence->name, scene_.delta() / scene_.h);
  summary_.variant = options.intact ? "intact (alpha folded to 1)" : "damaged (reads alpha)";
  summary_.effects.push_back(fmt::format("elasticity: law {} ({} kernels), influence {}", law->name, summary_.variant,
                                         influence->name));
  for (const auto& e : model_.effects) summary_.effects.push_back(e->describe());
  u_.assign(static_cast<std::size_t>(model_.particles.size()) * model_.particles.dim, 0.0);
  summary_.setup_seconds = seconds_since(t0);
  log_(fmt::format("{}: {} particles, {} bonds, delta = {:.6g} (delta/h = {:.4g}), setup {:.3f} s", scene_.file,
                   summary_.particles, summary_.bonds, scene_.delta(), scene_.delta() / scene_.h, summary_.setup_seconds));
  for (const auto& e : summary_.effects) log_("  effect: " + e);
  for (const auto& w : summary_.warnings) log_("  warning: " + w);
  log_("  solver path: " + summary_.solver_path);
  log_(fmt::format("  families: smallest weighted volume {:.3g} of a full horizon's (particle {}), largest shape-tensor "
                   "condition number {:.3g} (particle {}), weakest response to a homogeneous strain {:.3g} of the strongest "
                   "(particle {})",
                   quality.worst_weighted_volume_ratio, quality.worst_weighted_volume_particle, quality.worst_condition,
                   quality.worst_condition_particle, modes.worst_ratio, modes.worst_particle));
  // Gram-matrix ratio 1e-4: the weakest strain gets under 1% of the strongest's force.
  // Cubic weights at delta/h = 1.5 (diagonal bonds weigh 2e-4) give 1e-5 and a crack
  // solution with 100% error; delta/h = 2 gives 1e-2 and 2%.
  if (modes.blind.empty() && modes.worst_ratio < 1e-4)
    log_(fmt::format("  warning: family {} responds to some homogeneous strain with under 1% of its strongest response "
                     "(Gram ratio {:.2g}): the law is nearly blind to it at this delta/h and influence; expect a poor solution",
                     modes.worst_particle, modes.worst_ratio));
  if (!modes.blind.empty())
    log_(fmt::format("  warning: {} famil(ies) give the law no stiffness against some homogeneous strain (particle {} first); "
                     "their neighbours' families hold them",
                     modes.blind.size(), modes.blind.front()));
}

NewtonSettings Simulation::newton_settings() const {
  const SolverSpec& sv = scene_.solver;
  NewtonSettings s;
  s.load_steps = sv.load_steps;
  s.max_iterations = sv.max_iterations;
  s.relative_tolerance = sv.tolerance;
  s.increment_tolerance = sv.increment_tolerance;
  s.matrix_free = plan_.matrix_free();
  s.matrix_free_preconditioner = plan_.short_horizon_preconditioner() ? MatrixFreePreconditioner::approximate_tangent
                                                                      : MatrixFreePreconditioner::jacobi;
  s.linear.method = s.matrix_free ? LinearMethod::automatic : plan_.linear;
  s.linear.preconditioner = plan_.preconditioner;
  s.linear.tolerance = sv.krylov_tolerance;
  s.linear.max_iterations = sv.krylov_max_iterations;
  s.linear.direct_max_nonzeros = sv.direct_max_nonzeros;
  s.krylov_tolerance = sv.krylov_tolerance;
  if (sv.krylov_max_iterations > 0) s.krylov_max_iterations = sv.krylov_max_iterations;
  else s.krylov_max_iterations = 20000;
  return s;
}

double Simulation::reference_error(const std::vector<double>& u) const {
  if (!scene_.reference) throw std::logic_error("reference_error: the scene has no reference field");
  return field_error(scene_, *scene_.reference, model_.particles, u);
}

void Simulation::smooth() {
  const abi::InfluenceDescriptor* w = abi::find_influence(scene_.output.smoothing_influence);
  u_smooth_ = smooth_field(model_.particles, model_.bonds, w->weight, u_, model_.particles.dim);
  double num = 0, den = 0;
  for (std::size_t i = 0; i < u_.size(); ++i) num += std::pow(u_[i] - u_smooth_[i], 2), den += u_[i] * u_[i];
  summary_.smoothing = w->name;
  summary_.oscillation = den > 0 ? std::sqrt(num / den) : 0.0;
  log_(fmt::format("  smoothing (paper 000 eq. 49, influence {}): |u - u_s| / |u| = {:.6e}", w->name, summary_.oscillation));
  if (scene_.reference) {
    summary_.smoothed_field_error = field_error(scene_, *scene_.reference, model_.particles, u_smooth_);
    log_(fmt::format("  field error of the smoothed solution (eq. 48): {:.6e}", summary_.smoothed_field_error));
  }
}

// No load at all: the solution is zero, and Newton would only chase the residual's
// rounding noise. A load that falls entirely on prescribed components (a traction on
// fixed particles) is taken by the constraints and does no work: warned, and no load.
bool Simulation::has_load(const DofMap& dofs) {
  const auto free_force = [&](const Effect& e) {
    std::vector<double> zero(u_.size(), 0.0), force(u_.size(), 0.0);
    e.add_forces(zero.data(), 1.0, force.data());
    return dofs.restrict_free(Eigen::Map<const Eigen::VectorXd>(force.data(), static_cast<Eigen::Index>(force.size()))).norm();
  };
  for (const BoundaryCondition& bc : scene_.boundary) {
    if (bc.kind != BoundaryCondition::Kind::Traction && bc.kind != BoundaryCondition::Kind::BodyForce) continue;
    if (free_force(*make_external_loads(scene_, model_.particles, std::span(&bc, 1))) > 0.0) continue;
    const std::string w = bc.where + ": the " + (bc.kind == BoundaryCondition::Kind::Traction ? "traction" : "body force") +
                          " acts only on components whose displacement is prescribed: the constraints take it and it "
                          "does no work (check the regions)";
    summary_.warnings.push_back(w);
    log_("  warning: " + w);
  }
  bool loaded = false;
  for (double v : dofs.prescribed()) loaded = loaded || v != 0.0;
  for (const auto& e : model_.effects) loaded = loaded || free_force(*e) > 0.0;
  if (!loaded) log_("  no load on a free component and no prescribed displacement: the solution is zero");
  return loaded;
}

RunSummary Simulation::run(bool write) {
  const auto t0 = std::chrono::steady_clock::now();
  const DofMap dofs = scene_constraints(scene_, model_.particles);
  check_scene_holds_body(scene_, model_.particles, model_.bonds, dofs);
  const bool loaded = has_load(dofs);

  std::vector<const Effect*> effects;
  for (const auto& e : model_.effects) effects.push_back(e.get());
  PeridynamicSystem system(*model_.assembler, effects, model_.approximation.get());
  Eigen::VectorXd u = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(u_.size()));
  const long long broken_before = broken_bond_count(model_.bonds);
  if (loaded) {
    NewtonSettings settings = newton_settings();
    settings.after_step = [&](int step, double load, const Eigen::VectorXd& v) { return after_load_step(step, load, v, dofs); };
    if (scene_.damage) settings.max_resolves = scene_.damage->max_resolves;
    if (plan_.backend == Backend::petsc) {
      const FamilyAssembler* pc = model_.approximation ? model_.approximation.get() : model_.assembler.get();
      summary_.newton = solve_distributed({model_.assembler.get(), pc, effects, &dofs, system.symmetric(), settings}, u, log_);
    } else {
      summary_.newton = NewtonSolver(settings, log_).solve(system, dofs, u);
    }
  } else {
    summary_.newton.converged = true;
    summary_.newton.unknowns = dofs.free_count();
  }
  summary_.solve_seconds = seconds_since(t0);
  if (model_.damage) {
    summary_.bonds_broken_by_damage = broken_bond_count(model_.bonds) - broken_before;
    summary_.broken_bonds = static_cast<int>(broken_bond_count(model_.bonds));
  }
  if (!summary_.newton.linear_choice.empty())
    log_(fmt::format("  linear solver: {} ({})", summary_.newton.linear_solver, summary_.newton.linear_choice));
  if (!summary_.newton.converged) throw std::runtime_error(summary_.newton.message);
  for (Eigen::Index i = 0; i < u.size(); ++i)
    if (!std::isfinite(u[i]))
      throw std::runtime_error(fmt::format("the solution is not finite at particle {} (law {})", i / model_.particles.dim, summary_.law));
  u_.assign(u.data(), u.data() + u.size());
  if (wants_stress(scene_)) stress_ = peridynamic_stress(*model_.assembler, u_.data());
  summary_.probes = evaluate_probes(scene_, model_.particles, probe_particles(scene_, model_.particles), u_, &stress_);
  log_zero_energy_content(model_.particles, model_.bonds, u_, summary_.law, log_);
  if (scene_.reference) {
    summary_.has_field_error = true;
    summary_.field_error = field_error(scene_, *scene_.reference, model_.particles, u_);
    log_(fmt::format("  field error against {} (paper 000 eq. 48): {:.6e}", scene_.reference->solution, summary_.field_error));
  }
  if (!scene_.output.smoothing_influence.empty()) smooth();
  std::vector<double> external(scene_.output.j_integral.empty() ? 0 : u_.size(), 0.0);
  for (const auto& e : model_.effects)
    if (!external.empty()) e->add_forces(u_.data(), 1.0, external.data());
  for (const JContour& c : scene_.output.j_integral) {
    summary_.j_integrals.push_back(j_integral(*model_.assembler, u_.data(), scene_.h, c, external.data()));
    log_(j_integral_line(summary_.j_integrals.back()));
  }
  for (const auto& p : summary_.probes) log_(probe_log_line(p));
  if (write) write_outputs();
  return summary_;
}

// After a converged load step every effect may change the model (damage evolution
// breaks bonds and updates the moments: effects/damage_evolution.cpp); any change
// means the step is solved again on the changed system.
long long Simulation::after_load_step(int step, double load, const Eigen::VectorXd& u, const DofMap& dofs) {
  long long changes = 0;
  for (const auto& e : model_.effects) changes += e->after_step(u.data());
  if (changes == 0) return 0;
  log_(fmt::format("  load {:.3g} (step {}/{}): {} bonds broke ({} broken in all); solving the step again", load, step,
                   scene_.solver.load_steps, changes, broken_bond_count(model_.bonds)));
  // A piece cut loose by the new crack faces would make K singular: say which.
  check_held(model_.particles, model_.bonds, dofs);
  return changes;
}

void Simulation::write_outputs() {
  const auto t1 = std::chrono::steady_clock::now();
  const int d = model_.particles.dim;
  std::vector<OutputField> fields;
  std::vector<double> material(model_.particles.material.begin(), model_.particles.material.end());
  fields.push_back({"material", 1, material});
  fields.push_back({"damage", 1, particle_damage(model_.bonds)});
  std::vector<double> force(u_.size());
  model_.assembler->internal_forces(u_.data(), force.data());
  fields.push_back({"internal_force", d, force});
  if (!u_smooth_.empty()) fields.push_back({"smoothed_displacement", d, u_smooth_});
  append_law_outputs(*model_.assembler, model_.particles, u_, fields);
  if (scene_.output.stress) fields.push_back({"stress", d * d, stress_});
  const std::string dir = scene_.output.directory;
  // The files form one result: when a signal stops the writing half-way, the files this
  // run already renamed into place go too (a result without its summary is partial).
  try {
    if (scene_.output.vtu) write_vtu_file(dir + "/result.vtu", model_.particles, u_, fields), summary_.files.push_back(dir + "/result.vtu");
    if (scene_.output.csv) write_csv_file(dir + "/result.csv", model_.particles, u_, fields), summary_.files.push_back(dir + "/result.csv");
    summary_.files.push_back(dir + "/summary.json");
    summary_.output_seconds = seconds_since(t1);
    write_file_atomically(dir + "/summary.json", summary_.json());
  } catch (const Interrupted&) {
    for (const std::string& f : summary_.files)
      if (f != dir + "/summary.json") std::remove(f.c_str());
    summary_.files.clear();
    throw;
  }
}

}  // namespace pd
