// A dynamic run (scene with a `dynamics` section) over a model: explicit dynamics with
// velocity Verlet (run_explicit, explicit_run.cpp) or adaptive dynamic relaxation to the
// static answer (run_relaxation, relaxation_run.cpp). The model owns what they read: the
// effects (timed loads, pre-cracks, damage evolution, the inertia and viscous damping) and
// the dof map with each constrained dof's motion in time. What the scene does not call
// for is not built: no damage object or damaged kernels without `damage` or cracks, no
// snapshot or checkpoint files unless asked, no rho V mass in relaxation (its fictitious
// density replaces it).
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "exec/step_executor.hpp"
#include "input/scene.hpp"
#include "model/model.hpp"
#include "output/particle_fields.hpp"
#include "run/run_summary.hpp"

namespace pd {

// One row of the time series (energies.csv).
struct SeriesRow {
  int step = 0;
  double time = 0, kinetic = 0, strain = 0, external_work = 0;
  long long broken_bonds = 0;
  double residual_ratio = 0;  // relaxation only
  std::vector<double> probes;
};

// The state of a dynamic run and the steps both loops share (dynamic_run.cpp: set-up,
// constraints, forces; dynamic_outputs.cpp: series, checkpoints, snapshots, files).
struct DynamicRun {
  using Log = std::function<void(const std::string&)>;
  const Scene& scene;
  Model& model;
  Log log;
  std::vector<std::vector<int>> probe_ids;
  std::vector<double> u, v;  // v: explicit dynamics only
  std::vector<SeriesRow> series;
  std::vector<std::pair<int, double>> snapshots;  // (step, time)
  RunSummary summary;

  bool explicit_dynamics() const { return scene.dynamics->method == DynamicsMethod::explicit_verlet; }
  double dt() const;               // the inertia's time step (1 for relaxation)
  DynamicsReport& start_report();  // summary.dynamics, new, with the method
  void apply_initial_conditions();
  void prescribe(double t) { model.dofs.apply_motion(t, u, v); }
  // The steps of this run on this process (forces, after-step effects, sums, gathers),
  // for the backend the scene's solver plan names (exec/step_executor.hpp). It reads u and
  // v in place: make it where the run will not move.
  std::unique_ptr<StepExecutor> make_steps();
  // Adds `line` (when not empty) to the summary's effects and logs it.
  void add_effect_line(const std::string& line);
  SeriesRow make_row(int step, double t, double residual_ratio) const;
  std::string series_csv_header() const;
  std::string series_csv_row(const SeriesRow& r) const;
  void restore(const std::string& path, int& step, std::vector<double>& scalars);
  void save_checkpoint(int step, const std::vector<double>& scalars);
  void write_snapshot(int step, double t);
  std::vector<OutputField> output_fields() const;
  // The peridynamic stress at u when the scene asks for it (wants_stress), else empty.
  std::vector<double> stress_field() const;
  void write_results();
  // The end of either run: bonds broken since broken_start, the probes, the solve time
  // since t0, the result files (write), the summary's log text. Returns the summary.
  RunSummary finish(long long broken_start, std::chrono::steady_clock::time_point t0, bool write);
  // The end on a process other than rank 0 (which alone reports and writes): the solve time.
  RunSummary finish_elsewhere(std::chrono::steady_clock::time_point t0);
};

// Refuses (std::invalid_argument) what the dynamic runs do not implement: obq quadrature.
void check_dynamic_scene(const Scene& scene);

// The model for `scene.dynamics` (after check_dynamic_scene): the assembler without a
// matrix (the loops need forces only) on dynamics.threads, the timed loads, pre-cracks,
// damage evolution and the inertia (with the viscous damping) or relaxation's density.
Model build_dynamic_model(const Scene& scene);

// Logs the set-up of a model built by build_dynamic_model and returns the run's state at
// t = 0. The model and scene must outlive it.
DynamicRun prepare_dynamic_run(Model& model, const Scene& scene, DynamicRun::Log log);

// Run from t = 0, or from scene.dynamics->restart when set, to the scene's last step
// (or `stop_after` > 0: ends after that step, as an interrupted run would, after writing
// the checkpoints due); write: the result files (rank 0's). Serially or over the MPI ranks
// as scene.solver.backend says (one loop each: explicit_run.cpp, relaxation_run.cpp).
// Throw on failure.
RunSummary run_explicit(DynamicRun& run, bool write, int stop_after);
RunSummary run_relaxation(DynamicRun& run, bool write, int stop_after);
inline RunSummary run_dynamic(DynamicRun& run, bool write = true, int stop_after = 0) {
  return run.explicit_dynamics() ? run_explicit(run, write, stop_after)
                                 : run_relaxation(run, write, stop_after);
}

}  // namespace pd
