// write_static_outputs: a static run's result files.
#include <chrono>
#include <cstdio>

#include "interrupt.hpp"
#include "output/atomic_file.hpp"
#include "run/result_fields.hpp"
#include "run/static_run.hpp"
#include "stopwatch.hpp"

namespace pd {

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
