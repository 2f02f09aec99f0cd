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
#include "run/dynamics_report.hpp"
#include "run/effects.hpp"
#include "solve/newton.hpp"

namespace pd {

class CriticalStretchDamage;

struct ProbeResult {
  std::string name;
  int particles = 0;
  double value = 0;      // mean displacement component over the region
  bool has_reference = false;
  double reference = 0;  // mean of the analytic field over the same particles
  double error = 0;      // |value - reference| (paper 000 eq. 36)
};

struct RunSummary {
  std::string scene, law, influence;
  int particles = 0;
  long long bonds = 0;  // counted once per direction
  int broken_bonds = 0;
  std::string variant;
  std::vector<std::string> effects;
  std::vector<std::string> warnings;  // the scene's and the setup's, each also logged as "  warning: ..."
  std::string solver_path;  // the linear-solver path and why (run/solver_path.hpp)
  NewtonResult newton;                    // static runs
  std::optional<long long> bonds_broken_by_damage;  // static runs with `damage`: broken between load steps
  std::optional<DynamicsReport> dynamics;  // dynamic and relaxation runs only
  std::vector<ProbeResult> probes;
  bool has_field_error = false;
  double field_error = 0;  // paper 000 eq. (48): sum |u_anal - u|^2 / sum |u_anal|^2
  // output.smoothing (paper 000 eq. 49): the influence used, the relative oscillation
  // sqrt(sum |u - u_s|^2 / sum |u|^2) and, with a reference, eq. (48) for u_s.
  std::string smoothing;
  double oscillation = 0;
  double smoothed_field_error = 0;
  double setup_seconds = 0, solve_seconds = 0, output_seconds = 0;
  std::vector<std::string> files;
  std::string text() const;  // the run summary for the log
  std::string json() const;  // the run summary, as written to summary.json
};

class Simulation {
 public:
  using Log = std::function<void(const std::string&)>;
  Simulation(Scene scene, Log log);
  ~Simulation();
  // Solves and writes the outputs; throws on failure (nothing half-written).
  RunSummary run(bool write_outputs = true);

  const Particles& particles() const { return particles_; }
  const Bonds& bonds() const { return bonds_; }
  const std::vector<double>& displacement() const { return u_; }
  // The displacement smoothed by output.smoothing (empty without it).
  const std::vector<double>& smoothed_displacement() const { return u_smooth_; }
  const Scene& scene() const { return scene_; }
  const FamilyAssembler& assembler() const { return *assembler_; }
  const CriticalStretchDamage* damage() const { return damage_.get(); }
  // Paper 000 eq. (48) of a displacement field (one value per particle and component)
  // against the scene's `reference`; throws std::logic_error when the scene has none.
  double reference_error(const std::vector<double>& u) const;

 private:
  NewtonSettings newton_settings() const;
  std::string matrix_free_preconditioner() const;  // "" (assembled), diagonal or approximate
  std::vector<ProbeResult> evaluate_probes() const;
  double field_error(const FieldSpec& reference, const std::vector<double>& u) const;
  void smooth();
  void write_outputs();
  Scene scene_;
  Log log_;
  Particles particles_;
  Bonds bonds_;
  std::unique_ptr<FamilyAssembler> assembler_;
  // Matrix-free runs with the short-horizon preconditioner: the law on delta = ratio h.
  Bonds short_bonds_;
  std::unique_ptr<FamilyAssembler> approximation_;
  std::vector<std::unique_ptr<Effect>> effects_;
  // Scenes with `damage`: bonds break between load steps (after_load_step), in the real
  // bonds and in the preconditioner's short ones alike.
  std::unique_ptr<CriticalStretchDamage> damage_, short_damage_;
  long long after_load_step(int step, double load, const Eigen::VectorXd& u, const DofMap& dofs);
  std::vector<double> u_, u_smooth_;
  RunSummary summary_;
};

}  // namespace pd
