// A static run over a model: plan the solver and set the model up for it
// (plan_static_run, static_setup.cpp), solve with Newton over the load steps
// (run_static, static_run.cpp), write the result files (write_static_outputs,
// static_outputs.cpp). `pd run` calls the three in turn after build_model.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "input/scene.hpp"
#include "model/model.hpp"
#include "run/run_summary.hpp"
#include "solve/solver_plan.hpp"

namespace pd {

using RunLog = std::function<void(const std::string&)>;

// A static run's plan, its summary and its answer.
struct StaticRun {
  SolverPlan plan;  // decided once, by plan_static_run
  RunSummary summary;
  std::vector<double> u;         // the displacement (zero until run_static)
  std::vector<double> u_smooth;  // smoothed by output.smoothing (empty without it)
  std::vector<double> stress;    // peridynamic stress [n*dim*dim], when wants_stress(scene)
};

// Plans the solver for the model (plan_solver), then attaches what the plan needs: the
// assembler (with a matrix unless matrix-free), the short-horizon approximation, the
// effects. Logs the set-up, the solver path and the families' checks.
StaticRun plan_static_run(Model& model, const Scene& scene, const RunLog& log);

// Solves (nothing when there is no load: u = 0) and evaluates probes, eq. 48 errors,
// smoothing and J-integrals into run.summary. Throws on failure.
void run_static(StaticRun& run, Model& model, const Scene& scene, const RunLog& log);

// result.vtu, result.csv and summary.json in output.directory (all or none).
void write_static_outputs(StaticRun& run, const Model& model, const Scene& scene);

}  // namespace pd
