#include "run/setup_report.hpp"

#include <fmt/core.h>

#include "material/law_history.hpp"

namespace pd {

void describe_model(RunSummary& summary, const Model& model, const Scene& scene) {
  summary.describe(scene, model);
  if (model.collocation) summary.effects.push_back(model.collocation_description);
  if (model.gauss_points) summary.effects.push_back(model.gauss_points->describe());
  summary.variant = model.assembler_options.intact ? "intact (alpha folded to 1)" : "damaged (reads alpha)";
  summary.effects.push_back(fmt::format("elasticity: law {} ({} kernels), influence {}", model.law->name,
                                        summary.variant, model.influence->name));
  if (model.has_history()) {
    const std::size_t values = model.bond_history.size() + model.particle_history.size();
    summary.effects.push_back(
        fmt::format("history: {} ({} values, {:.3g} MB), committed after each converged step",
                    describe_history(*model.law), values, 8e-6 * static_cast<double>(values)));
  }
  for (const auto& e : model.effects) summary.effects.push_back(e->describe());
}

void log_setup(const RunSummary& summary, const Scene& scene, const RunLog& log) {
  log(fmt::format("{}: {} particles, {} bonds, delta = {:.6g} (delta/h = {:.4g}), setup {:.3f} s", scene.file,
                  summary.particles, summary.bonds, scene.delta(), scene.delta() / scene.h,
                  summary.setup_seconds));
  for (const auto& e : summary.effects) log("  effect: " + e);
  for (const auto& w : summary.warnings) log("  warning: " + w);
}

}  // namespace pd
