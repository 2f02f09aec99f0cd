// A dynamic run (scene with a `dynamics` section): explicit dynamics with velocity
// Verlet, or adaptive dynamic relaxation to the static answer; optional critical-stretch
// damage; time-dependent loads; time series, .vtu snapshots with a .pvd collection,
// checkpoints and restarts. `pd run` uses it instead of Simulation when the scene has
// a `dynamics` section. What the scene does not call for is not built: no damage object
// or damaged kernels without `damage` or cracks, no snapshot or checkpoint files unless
// asked, no mass array in relaxation (its fictitious density replaces it).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "assembly/assembler.hpp"
#include "damage/critical_stretch.hpp"
#include "output/particle_fields.hpp"
#include "input/scene.hpp"
#include "model/model.hpp"
#include "run/constraints.hpp"
#include "effects/loads.hpp"
#include "run/simulation.hpp"

namespace pd {

// One row of the time series (energies.csv).
struct SeriesRow {
  int step = 0;
  double time = 0, kinetic = 0, strain = 0, external_work = 0;
  long long broken_bonds = 0;
  double residual_ratio = 0;  // relaxation only
  std::vector<double> probes;
};

class DynamicSimulation {
 public:
  using Log = std::function<void(const std::string&)>;
  DynamicSimulation(Scene scene, Log log);
  ~DynamicSimulation();
  // Runs from t = 0, or from scene.dynamics->restart when set, to the scene's last step
  // (or `stop_after` > 0: ends after that step, as an interrupted run would, after
  // writing the checkpoints due). Throws on failure.
  RunSummary run(bool write_outputs = true, int stop_after = 0);

  const Particles& particles() const { return model_.particles; }
  const Bonds& bonds() const { return model_.bonds; }
  const std::vector<double>& displacement() const { return u_; }
  const std::vector<double>& velocity() const { return v_; }
  const std::vector<SeriesRow>& series() const { return series_; }
  const FamilyAssembler& assembler() const { return *model_.assembler; }
  const CriticalStretchDamage* damage() const { return model_.damage; }
  bool has_masses() const { return !mass_.empty(); }
  const Scene& scene() const { return scene_; }

 private:
  void setup_constraints();
  void apply_initial_conditions();
  void prescribe(double t);
  // Every effect's after_step at the current u (damage: bonds break); true when any changed the model.
  bool after_step();
  // f = f_int(u) + loads(t); g = the external forces for the work (loads on free dofs,
  // reactions -f_int on constrained ones).
  void forces(double t, std::vector<double>& f, std::vector<double>& g) const;
  SeriesRow make_row(int step, double t, double residual_ratio) const;
  std::string series_csv_header() const;
  std::string series_csv_row(const SeriesRow& r) const;
  void restore(const std::string& path, int& step, std::vector<double>& scalars);
  void save_checkpoint(int step, const std::vector<double>& scalars);
  void write_snapshot(int step, double t);
  std::vector<OutputField> output_fields() const;
  // The peridynamic stress at u_ when the scene asks for it (wants_stress), else empty.
  std::vector<double> stress_field() const;
  void write_results();
  RunSummary run_explicit(bool write, int stop_after);
  RunSummary run_relaxation(bool write, int stop_after);

  const Scene scene_;  // never changed after reading
  Log log_;
  Model model_;  // owns the effects: the timed loads, the pre-cracks, damage evolution
  std::vector<PrescribedDof> prescribed_;
  std::vector<TiedDof> ties_;  // fictitious layers: set from the body by prescribe()
  std::vector<int> free_, constrained_;
  std::vector<std::vector<int>> probe_ids_;
  std::vector<double> mass_;             // explicit only: rho V per dof
  std::vector<double> density_;          // relaxation only: the fictitious D_ii
  std::vector<double> u_, v_;
  double dt_ = 0, dt_stable_ = 0;
  std::vector<SeriesRow> series_;
  std::vector<std::pair<int, double>> snapshots_;  // (step, time)
  RunSummary summary_;
};

}  // namespace pd
