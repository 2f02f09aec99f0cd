// A dynamic run as one object, for the tests and tools that hold a run and look at its
// state after it: the scene, the model built from it and the run's state
// (run/dynamic_run.hpp, where the runs themselves are). `pd run` calls those directly.
#pragma once

#include "run/dynamic_run.hpp"

namespace pd {

class DynamicSimulation {
 public:
  using Log = DynamicRun::Log;
  DynamicSimulation(Scene scene, Log log)
      : scene_(std::move(scene)),
        model_(build_dynamic_model(scene_)),
        run_(prepare_dynamic_run(model_, scene_, std::move(log))) {}
  DynamicSimulation(const DynamicSimulation&) = delete;
  DynamicSimulation& operator=(const DynamicSimulation&) = delete;
  // Runs from t = 0, or from scene.dynamics->restart when set (run_dynamic).
  RunSummary run(bool write_outputs = true, int stop_after = 0) {
    return run_dynamic(run_, write_outputs, stop_after);
  }

  const Particles& particles() const { return model_.particles; }
  const Bonds& bonds() const { return model_.bonds; }
  const std::vector<double>& displacement() const { return run_.u; }
  const std::vector<double>& velocity() const { return run_.v; }
  // A law with memory: the committed per-bond history (Model::bond_history); empty otherwise.
  const std::vector<double>& bond_history() const { return model_.bond_history; }
  const std::vector<double>& particle_history() const { return model_.particle_history; }
  const std::vector<SeriesRow>& series() const { return run_.series; }
  const ForceOperator& assembler() const { return *model_.assembler; }
  const CriticalStretchDamage* damage() const { return model_.damage; }
  bool has_masses() const { return run_.explicit_dynamics(); }
  const Scene& scene() const { return scene_; }

 private:
  const Scene scene_;  // never changed after reading
  Model model_;
  DynamicRun run_;
};

}  // namespace pd
