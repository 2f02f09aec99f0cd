// plan_static_run: the solver plan and the model's assemblers and effects for it.
#include <fmt/core.h>

#include <algorithm>
#include <chrono>

#include "assembly/strain_modes.hpp"
#include "discretize/discretization.hpp"
#include "run/static_run.hpp"
#include "stopwatch.hpp"

namespace pd {

namespace {
// What the solver plan needs of the model (mean family size: bonds per particle).
ProblemSize problem_size(const Model& model, const Scene& scene, double short_family_size) {
  return {model.particles.size(), 2.0 * static_cast<double>(model.bond_count) / model.particles.size(),
          model.particles.dim,    scene.delta() / scene.h,
          short_family_size,      coupling_of_law(model.law->n_states) == Coupling::pairwise};
}
}  // namespace

StaticRun plan_static_run(Model& model, const Scene& scene, const RunLog& log) {
  const auto t0 = std::chrono::steady_clock::now();
  StaticRun run;
  RunSummary& summary = run.summary;
  summary.describe(scene, model);
  const abi::LawDescriptor* law = model.law;
  const abi::InfluenceDescriptor* influence = model.influence;
  const FamilyQualityReport& quality = model.quality;
  // Simulate only what the scene calls for: no broken bond -> the variant without alpha;
  // matrix-free Newton-Krylov -> no sparsity pattern and no slot table.
  const double short_delta = std::min(scene.delta(), scene.solver.preconditioner_ratio * scene.h);
  // Only `auto` sizes the preconditioner before choosing (a pass over every bond).
  const double short_family = plan_needs_short_family_size(scene.solver)
                                  ? mean_short_family_size(model.bonds, short_delta, influence->weight)
                                  : -1;
  run.plan = plan_solver(scene.solver, problem_size(model, scene, short_family));
  summary.solver_path = run.plan.reason;
  // PETSc with delta <= ratio h: its preconditioning matrix is the tangent's own.
  if (run.plan.short_horizon_preconditioner() &&
      !(run.plan.backend == Backend::petsc && short_delta >= scene.delta()))
    attach_short_horizon(model, scene, short_delta);
  if (run.plan.short_horizon_preconditioner() && model.collocation)
    summary.solver_path +=
        "; with quadrature obq the preconditioner is the collocation tangent itself (a shorter "
        "horizon's volume-rule stiffness does not approximate it)";
  const AssemblerOptions options = attach_assembler(model, scene, !run.plan.matrix_free());
  attach_effects(model, scene);
  if (model.collocation) summary.effects.push_back(model.collocation_description);
  if (model.gauss_points) summary.effects.push_back(model.gauss_points->describe());
  // The check reads the law on the bond families; a Gauss-point model has its bonds too,
  // and the check is of the law on that horizon.
  std::unique_ptr<FamilyAssembler> on_bonds;
  const FamilyAssembler* families = model.assembler->bond_families();
  if (!families) {
    AssemblerOptions bond_options = options;
    bond_options.gauss_points = nullptr;
    bond_options.matrix = false;
    on_bonds =
        std::make_unique<FamilyAssembler>(model.particles, model.bonds, *law, model.params, bond_options);
    families = on_bonds.get();
  }
  const StrainModeReport modes = check_strain_modes(*families, influence->name, scene.delta() / scene.h);
  summary.variant = options.intact ? "intact (alpha folded to 1)" : "damaged (reads alpha)";
  summary.effects.push_back(fmt::format("elasticity: law {} ({} kernels), influence {}", law->name,
                                        summary.variant, influence->name));
  for (const auto& e : model.effects) summary.effects.push_back(e->describe());
  run.u.assign(static_cast<std::size_t>(model.particles.size()) * model.particles.dim, 0.0);
  summary.setup_seconds = model.build_seconds + seconds_since(t0);
  log(fmt::format("{}: {} particles, {} bonds, delta = {:.6g} (delta/h = {:.4g}), setup {:.3f} s", scene.file,
                  summary.particles, summary.bonds, scene.delta(), scene.delta() / scene.h,
                  summary.setup_seconds));
  for (const auto& e : summary.effects) log("  effect: " + e);
  for (const auto& w : summary.warnings) log("  warning: " + w);
  log("  solver path: " + summary.solver_path);
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
  return run;
}

}  // namespace pd
