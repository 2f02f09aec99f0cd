// A static run as one object, for the tests and tools (the study runner) that hold a run
// and look at its answer after it: the scene, the model built from it and the run
// (run/static_run.hpp, where the stages are). `pd run` calls the stages directly.
#pragma once

#include <stdexcept>

#include "run/run_outputs.hpp"
#include "run/static_run.hpp"

namespace pd {

class Simulation {
 public:
  using Log = RunLog;
  // Builds the model and plans the solver (setup, timed).
  Simulation(Scene scene, Log log)
      : scene_(std::move(scene)), log_(std::move(log)), model_(build_static_model(scene_, run_)) {
    describe_static_run(run_, model_, scene_, log_);
  }
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;
  // Solves and writes the outputs; throws on failure (nothing half-written).
  RunSummary run(bool write_outputs = true) {
    run_static(run_, model_, scene_, log_);
    if (write_outputs) write_static_outputs(run_, model_, scene_);
    return run_.summary;
  }

  const Particles& particles() const { return model_.particles; }
  const Bonds& bonds() const { return model_.bonds; }
  const std::vector<double>& displacement() const { return run_.u; }
  // A law with memory: the committed per-bond history after the run (Model::bond_history).
  const std::vector<double>& bond_history() const { return model_.bond_history; }
  const std::vector<double>& particle_history() const { return model_.particle_history; }
  // The displacement smoothed by output.smoothing (empty without it).
  const std::vector<double>& smoothed_displacement() const { return run_.u_smooth; }
  const Scene& scene() const { return scene_; }
  const SolverPlan& solver_plan() const { return run_.plan; }
  const ForceOperator& assembler() const { return *model_.assembler; }
  const Model& model() const { return model_; }
  const CriticalStretchDamage* damage() const { return model_.damage; }
  // Paper 000 eq. (48) of a displacement field (one value per particle and component)
  // against the scene's `reference`; throws std::logic_error when the scene has none.
  double reference_error(const std::vector<double>& u) const {
    if (!scene_.reference) throw std::logic_error("reference_error: the scene has no reference field");
    return field_error(scene_, *scene_.reference, model_.particles, u);
  }

 private:
  const Scene scene_;  // never changed after reading
  Log log_;
  StaticRun run_;  // planned while model_ is built (declared first)
  Model model_;
};

}  // namespace pd
