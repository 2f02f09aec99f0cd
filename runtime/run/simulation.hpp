// A static run: scene -> particles and families -> effects -> Newton solve -> outputs.
// Setup (constructor) and solve (run) are timed separately.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "assembly/assembler.hpp"
#include "damage/critical_stretch.hpp"
#include "input/scene.hpp"
#include "model/model.hpp"
#include "run/run_summary.hpp"
#include "effects/loads.hpp"
#include "solve/newton.hpp"
#include "solve/solver_plan.hpp"

namespace pd {

class CriticalStretchDamage;

class Simulation {
 public:
  using Log = std::function<void(const std::string&)>;
  Simulation(Scene scene, Log log);
  ~Simulation();
  // Solves and writes the outputs; throws on failure (nothing half-written).
  RunSummary run(bool write_outputs = true);

  const Particles& particles() const { return model_.particles; }
  const Bonds& bonds() const { return model_.bonds; }
  const std::vector<double>& displacement() const { return u_; }
  // The displacement smoothed by output.smoothing (empty without it).
  const std::vector<double>& smoothed_displacement() const { return u_smooth_; }
  const Scene& scene() const { return scene_; }
  const SolverPlan& solver_plan() const { return plan_; }
  const FamilyAssembler& assembler() const { return *model_.assembler; }
  const CriticalStretchDamage* damage() const { return model_.damage; }
  // Paper 000 eq. (48) of a displacement field (one value per particle and component)
  // against the scene's `reference`; throws std::logic_error when the scene has none.
  double reference_error(const std::vector<double>& u) const;

 private:
  NewtonSettings newton_settings() const;
  bool has_load(const DofMap& dofs);  // false (and logged why) when the solution is zero
  void smooth();
  void write_outputs();
  const Scene scene_;  // never changed after reading
  Log log_;
  SolverPlan plan_;  // decided once, in the constructor
  Model model_;  // owns the effects; damage breaks bonds between load steps (after_load_step)
  long long after_load_step(int step, double load, const Eigen::VectorXd& u, const DofMap& dofs);
  std::vector<double> u_, u_smooth_;
  std::vector<double> stress_;  // peridynamic stress [n*dim*dim], when wants_stress(scene)
  RunSummary summary_;
};

}  // namespace pd
