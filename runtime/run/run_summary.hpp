// What a run reports: the log's closing summary and summary.json (run_summary.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "input/scene.hpp"
#include "model/model.hpp"
#include "post/j_integral.hpp"
#include "run/dynamics_report.hpp"
#include "solve/newton.hpp"

namespace pd {

struct ProbeResult {
  std::string name;
  int particles = 0;
  double value = 0;  // mean displacement component over the region
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
  std::string solver_path;            // the linear-solver path and why (SolverPlan::reason)
  NewtonResult newton;                // static runs
  std::optional<long long> bonds_broken_by_damage;  // static runs with `damage`: broken between load steps
  std::optional<DynamicsReport> dynamics;           // dynamic and relaxation runs only
  std::vector<ProbeResult> probes;
  bool has_field_error = false;
  double field_error = 0;  // paper 000 eq. (48): sum |u_anal - u|^2 / sum |u_anal|^2
  double rms_error = 0;    // paper 001 §4: RMS of |u - u_anal| over the rms_particles free particles
  int rms_particles = 0;
  // output.smoothing (paper 000 eq. 49): the influence used, the relative oscillation
  // sqrt(sum |u - u_s|^2 / sum |u|^2) and, with a reference, eq. (48) for u_s.
  std::string smoothing;
  double oscillation = 0;
  double smoothed_field_error = 0;
  std::vector<JIntegralResult> j_integrals;  // output.j_integral (paper 004)
  double setup_seconds = 0, solve_seconds = 0, output_seconds = 0;
  std::vector<std::string> files;
  // The scene, law, influence and count fields from the model.
  void describe(const Scene& scene, const DiscretizedBody& model);
  std::string text() const;  // the run summary for the log
  std::string json() const;  // the run summary, as written to summary.json
};

}  // namespace pd
