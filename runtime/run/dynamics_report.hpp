// What a dynamic or relaxation run reports in RunSummary (and summary.json: "dynamics").
#pragma once

#include <string>

#include "input/dynamics_spec.hpp"

namespace pd {

struct DynamicsReport {
  DynamicsMethod method = DynamicsMethod::explicit_verlet;  // velocity Verlet or ADR
  int first_step = 0;                                       // 0, or the checkpoint's step on a restart
  int last_step = 0;                                        // the step (iteration) the run ended at
  double dt = 0;                                            // the step used (explicit); 1 for relaxation
  double dt_stable = 0;  // the Gershgorin estimate of the stable step (explicit)
  std::string dt_rule;   // how dt was chosen
  double damping = 0;    // explicit: the viscous coefficient; relaxation: the last adaptive c
  double time = 0;       // simulated time at the end
  double kinetic = 0, strain = 0, external_work = 0;
  bool strain_available = false;  // false when the law has no energy kernel
  bool converged = false;         // relaxation: |r_free| <= tolerance x reference
  double residual_ratio = 0;      // relaxation: the last |r_free| / reference
  long long bonds_broken = 0;     // by damage evolution during the run (each bond once)
  std::string restarted_from;
  int checkpoints = 0, snapshots = 0;
};

}  // namespace pd
