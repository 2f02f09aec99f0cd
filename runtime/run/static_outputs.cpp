// write_static_outputs: a static run's result files.
#include <fmt/core.h>

#include <chrono>
#include <cstdio>

#include "interrupt.hpp"
#include "output/atomic_file.hpp"
#include "run/result_fields.hpp"
#include "run/static_run.hpp"
#include "stopwatch.hpp"

namespace pd {

namespace {
// step, load (and time, with solver.duration) and one column per probe (named as in the
// scene), one row per standing step; doubles to 17 significant digits, so the file is the
// run's values.
std::string load_steps_csv(const StaticRun& run, const Scene& scene) {
  const bool timed = scene.solver.duration > 0;
  std::string out = timed ? "step,load,time" : "step,load";
  for (const Probe& p : scene.probes) out += "," + p.name;
  out += "\n";
  for (const StaticRun::LoadStepRow& row : run.load_step_rows) {
    out += fmt::format("{},{:.17g}", row.step, row.load);
    if (timed) out += fmt::format(",{:.17g}", row.time);
    for (double v : row.probes) out += fmt::format(",{:.17g}", v);
    out += "\n";
  }
  return out;
}
}  // namespace

void write_static_outputs(StaticRun& run, const Model& model, const Scene& scene) {
  const auto t1 = std::chrono::steady_clock::now();
  RunSummary& summary = run.summary;
  const std::vector<double> no_velocity;
  const std::vector<OutputField> fields =
      result_fields({model, scene, run.u, no_velocity, run.u_smooth, run.stress, /*dynamic=*/false});
  const std::string dir = scene.output.directory;
  // The files form one result: when a signal stops the writing half-way, the files this
  // run already renamed into place go too (a result without its summary is partial).
  try {
    write_result_files(dir, model.particles, run.u, fields, scene.output, summary.files);
    if (!run.load_step_rows.empty()) {
      summary.files.push_back(dir + "/load_steps.csv");  // listed first: an interrupt removes it
      write_file_atomically(dir + "/load_steps.csv", load_steps_csv(run, scene));
    }
    summary.files.push_back(dir + "/summary.json");
    summary.output_seconds = seconds_since(t1);
    write_file_atomically(dir + "/summary.json", summary.json());
  } catch (const Interrupted&) {
    for (const std::string& f : summary.files)
      if (f != dir + "/summary.json") std::remove(f.c_str());
    summary.files.clear();
    throw;
  }
}

}  // namespace pd
