// plan_static_run: the solver plan from the discretized body, what it asks of the model,
// and the set-up's description and checks once the model is built.
#include <fmt/core.h>

#include <algorithm>
#include <chrono>

#include "assembly/strain_modes.hpp"
#include "discretize/discretization.hpp"
#include "run/setup_report.hpp"
#include "run/static_run.hpp"
#include "stopwatch.hpp"

namespace pd {

namespace {
// What the solver plan needs of the body (mean family size: bonds per particle).
ProblemSize problem_size(const DiscretizedBody& body, const Scene& scene, double short_family_size) {
  return {body.particles.size(), 2.0 * static_cast<double>(body.bond_count) / body.particles.size(),
          body.particles.dim,    scene.delta() / scene.h,
          short_family_size,     coupling_of_law(body.law->n_states) == Coupling::pairwise};
}

// The preconditioner's horizon: delta, or preconditioner_ratio h when that is shorter.
double short_delta_of(const Scene& scene) {
  return std::min(scene.delta(), scene.solver.preconditioner_ratio * scene.h);
}

// The check of the law's response to homogeneous strains reads the law on the bond
// families; a Gauss-point model has its bonds too, and the check is of the law on that horizon.
StrainModeReport strain_modes_of(const Model& model, const Scene& scene) {
  const FamilyAssembler* families = model.assembler->bond_families();
  std::unique_ptr<FamilyAssembler> on_bonds;
  if (!families) {
    AssemblerOptions bond_options = model.assembler_options;
    bond_options.gauss_points = nullptr;
    bond_options.matrix = false;
    on_bonds = std::make_unique<FamilyAssembler>(model.particles, model.bonds, *model.law, model.params,
                                                 bond_options);
    families = on_bonds.get();
  }
  return check_strain_modes(*families, model.influence->name, scene.delta() / scene.h);
}

void log_family_checks(const Model& model, const StrainModeReport& modes, const RunLog& log) {
  const FamilyQualityReport& quality = model.quality;
  log(fmt::format(
      "  families: smallest weighted volume {:.3g} of a full horizon's (particle {}), largest shape-tensor "
      "condition number {:.3g} (particle {}), weakest response to a homogeneous strain {:.3g} of the "
      "strongest "
      "(particle {})",
      quality.worst_weighted_volume_ratio, quality.worst_weighted_volume_particle, quality.worst_condition,
      quality.worst_condition_particle, modes.worst_ratio, modes.worst_particle));
  // Gram-matrix ratio 1e-4: the weakest strain gets under 1% of the strongest's force.
  // Cubic weights at delta/h = 1.5 (diagonal bonds weigh 2e-4) give 1e-5 and a crack
  // solution with 100% error; delta/h = 2 gives 1e-2 and 2%.
  if (modes.blind.empty() && modes.worst_ratio < 1e-4)
    log(fmt::format(
        "  warning: family {} responds to some homogeneous strain with under 1% of its strongest response "
        "(Gram ratio {:.2g}): the law is nearly blind to it at this delta/h and influence; expect a poor "
        "solution",
        modes.worst_particle, modes.worst_ratio));
  if (!modes.blind.empty())
    log(
        fmt::format("  warning: {} famil(ies) give the law no stiffness against some homogeneous strain "
                    "(particle {} first); "
                    "their neighbours' families hold them",
                    modes.blind.size(), modes.blind.front()));
}
}  // namespace

StaticRun plan_static_run(const DiscretizedBody& body, const Scene& scene) {
  StaticRun run;
  // Only `auto` sizes the preconditioner before choosing (a pass over every bond).
  const double short_family =
      plan_needs_short_family_size(scene.solver)
          ? mean_short_family_size(body.bonds, short_delta_of(scene), body.influence->weight)
          : -1;
  run.plan = plan_solver(scene.solver, problem_size(body, scene, short_family));
  return run;
}

ModelPlan static_model_plan(const StaticRun& run, const Scene& scene) {
  // Simulate only what the scene calls for: matrix-free Newton-Krylov -> no sparsity
  // pattern and no slot table; PETSc with delta <= ratio h: its preconditioning matrix is
  // the tangent's own, no approximation.
  ModelPlan plan;
  plan.matrix = !run.plan.matrix_free();
  const double short_delta = short_delta_of(scene);
  if (run.plan.short_horizon_preconditioner() &&
      !(run.plan.backend == Backend::petsc && short_delta >= scene.delta()))
    plan.short_delta = short_delta;
  return plan;
}

Model build_static_model(const Scene& scene, StaticRun& run) {
  return Model(scene, [&](const DiscretizedBody& body) {
    run = plan_static_run(body, scene);
    return static_model_plan(run, scene);
  });
}

void describe_static_run(StaticRun& run, const Model& model, const Scene& scene, const RunLog& log) {
  const auto t0 = std::chrono::steady_clock::now();
  RunSummary& summary = run.summary;
  describe_model(summary, model, scene);
  summary.solver_path = run.plan.reason;
  if (run.plan.short_horizon_preconditioner() && model.collocation)
    summary.solver_path +=
        "; with quadrature obq the preconditioner is the collocation tangent itself (a shorter "
        "horizon's volume-rule stiffness does not approximate it)";
  const StrainModeReport modes = strain_modes_of(model, scene);
  run.u.assign(static_cast<std::size_t>(model.particles.size()) * model.particles.dim, 0.0);
  summary.setup_seconds = model.build_seconds + seconds_since(t0);
  log_setup(summary, scene, log);
  log("  solver path: " + summary.solver_path);
  log_family_checks(model, modes, log);
}

}  // namespace pd
