// The dynamic runs' set-up, initial conditions, and forces at time t. The two loops are
// in explicit_run.cpp and relaxation_run.cpp, the series, checkpoints and files in
// dynamic_outputs.cpp.
#include "run/dynamic_run.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "discretize/discretization.hpp"
#include "effects/inertia.hpp"
#include "exec/serial_steps.hpp"
#include "input/yaml_keys.hpp"
#include "petsc/rank_steps_factory.hpp"
#include "run/run_outputs.hpp"
#include "run/setup_report.hpp"
#include "stopwatch.hpp"

namespace pd {

void check_dynamic_scene(const Scene& scene) {
  if (!scene.dynamics) throw std::invalid_argument("dynamic run: the scene has no dynamics section");
  if (!quadrature_rule(scene.quadrature).dynamics)
    throw std::invalid_argument(scene.file +
                                ": domain.quadrature: " + std::string(name_of(scene.quadrature)) +
                                " is implemented for static solves only");
}

Model build_dynamic_model(const Scene& scene) {
  check_dynamic_scene(scene);
  return Model(scene,
               ModelPlan{.matrix = false, .threads = scene.dynamics->threads, .short_delta = std::nullopt});
}

DynamicRun prepare_dynamic_run(Model& model, const Scene& scene, DynamicRun::Log log) {
  check_dynamic_scene(scene);
  if (!model.inertia) throw std::logic_error("prepare_dynamic_run: the model was not built for dynamics");
  const auto t0 = std::chrono::steady_clock::now();
  const DynamicsSpec& dyn = *scene.dynamics;
  DynamicRun run{scene, model, std::move(log), {}, {}, {}, {}, {}, {}};
  RunSummary& summary = run.summary;
  describe_model(summary, model, scene);
  if (run.explicit_dynamics() && !dyn.initial.empty())
    summary.effects.push_back(fmt::format("initial conditions: {} region(s)", dyn.initial.size()));
  run.probe_ids = probe_particles(scene, model.particles);
  const std::size_t N = static_cast<std::size_t>(model.particles.size()) * model.particles.dim;
  run.u.assign(N, 0.0);
  if (run.explicit_dynamics()) {
    run.v.assign(N, 0.0);
    if (dyn.dt > model.inertia->dt_stable)
      run.log(fmt::format("  warning: dt = {:.6g} exceeds the stable estimate {:.6g}", dyn.dt,
                          model.inertia->dt_stable));
  }
  summary.newton.unknowns = static_cast<std::int64_t>(model.dofs.free_count());
  summary.setup_seconds = model.build_seconds + seconds_since(t0);
  log_setup(summary, scene, run.log);
  return run;
}

double DynamicRun::dt() const { return model.inertia->dt; }

DynamicsReport& DynamicRun::start_report() {
  summary.dynamics = DynamicsReport{};
  summary.dynamics->method = scene.dynamics->method;
  return *summary.dynamics;
}

void DynamicRun::apply_initial_conditions() {
  const int d = model.particles.dim;
  for (const InitialCondition& ic : scene.dynamics->initial) {
    const auto ids = region_particles(ic.region, model.particles, scene);
    if (ids.empty()) throw SceneError(ic.where + ": the region holds no particle");
    for (int p : ids) {
      double shape = 1;
      if (ic.gaussian) {
        const double z = (model.particles.position(p)[ic.axis] - ic.center) / ic.width;
        shape = std::exp(-0.5 * z * z);
      }
      for (int c = 0; c < d; ++c) {
        double linear = 0;  // gradient (x - origin), zero without a gradient
        for (int j = 0; ic.has_gradient && j < d; ++j)
          linear += ic.gradient[c][j] * (model.particles.position(p)[j] - ic.origin[j]);
        u[static_cast<std::size_t>(p) * d + c] = shape * ic.displacement[c] + linear;
        if (!v.empty()) v[static_cast<std::size_t>(p) * d + c] = shape * ic.velocity[c];
      }
    }
  }
}

std::unique_ptr<StepExecutor> DynamicRun::make_steps() {
  const StepState state{model, u, v, scene.file};
  switch (scene.solver.backend) {
    case Backend::serial:
      return std::make_unique<SerialSteps>(state);
    case Backend::petsc:
      return make_rank_steps(state);
  }
  throw std::logic_error("DynamicRun::make_steps: unknown backend");
}

void DynamicRun::add_effect_line(const std::string& line) {
  if (line.empty()) return;
  summary.effects.push_back(line);
  log("  effect: " + line);
}

RunSummary DynamicRun::finish_elsewhere(std::chrono::steady_clock::time_point t0) {
  summary.solve_seconds = seconds_since(t0);
  return summary;
}

}  // namespace pd
