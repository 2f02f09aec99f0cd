// A static run over a model: build the model with the solver planned from its body
// (build_static_model, static_setup.cpp) and describe it, solve with Newton over the load
// steps (run_static, static_run.cpp), write the result files (write_static_outputs,
// static_outputs.cpp). `pd run` calls them in turn.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "input/scene.hpp"
#include "model/model.hpp"
#include "run/run_summary.hpp"
#include "run/setup_report.hpp"  // RunLog
#include "solve/solver_plan.hpp"

namespace pd {

// A static run's plan, its summary and its answer.
struct StaticRun {
  SolverPlan plan;  // decided once, by plan_static_run
  RunSummary summary;
  std::vector<double> u;         // the displacement (zero until run_static)
  std::vector<double> u_smooth;  // smoothed by output.smoothing (empty without it)
  std::vector<double> stress;    // peridynamic stress [n*dim*dim], when wants_stress(scene)
  // With several load steps and probes: after every load step that stands, its load factor
  // and each probe's value there (the path a load_path traces: a stress-strain loop),
  // written to load_steps.csv; with solver.duration, the physical time it ends at too.
  struct LoadStepRow {
    int step = 0;
    double load = 0;
    double time = 0;
    std::vector<double> probes;
  };
  std::vector<LoadStepRow> load_step_rows;
  double time = 0;  // the end of the increment being solved (solver.duration), 0 without
};

// Plans the solver for the discretized body (plan_solver): the run with its plan, nothing solved.
StaticRun plan_static_run(const DiscretizedBody& body, const Scene& scene);

// What that plan asks of the model: a matrix unless matrix-free, the short-horizon
// approximation when the plan's preconditioner is one.
ModelPlan static_model_plan(const StaticRun& run, const Scene& scene);

// The model, with `run` planned from its body in between the two phases (model/model.hpp).
Model build_static_model(const Scene& scene, StaticRun& run);

// The summary's description of the set-up; logs it, the solver path and the families'
// checks (and warns of a law nearly blind to a homogeneous strain). Sets u = 0.
void describe_static_run(StaticRun& run, const Model& model, const Scene& scene, const RunLog& log);

// Solves (nothing when there is no load: u = 0) and evaluates probes, eq. 48 errors,
// smoothing and J-integrals into run.summary. Throws on failure.
void run_static(StaticRun& run, Model& model, const Scene& scene, const RunLog& log);

// result.vtu, result.csv, load_steps.csv (when run.load_step_rows has rows) and summary.json
// in output.directory (all or none).
void write_static_outputs(StaticRun& run, const Model& model, const Scene& scene);

}  // namespace pd
