// write_static_outputs: a static run's result files.
#include <chrono>
#include <cstdio>

#include "damage/critical_stretch.hpp"
#include "interrupt.hpp"
#include "output/atomic_file.hpp"
#include "output/csv_writer.hpp"
#include "output/vtu_writer.hpp"
#include "run/run_outputs.hpp"
#include "run/static_run.hpp"
#include "stopwatch.hpp"

namespace pd {

void write_static_outputs(StaticRun& run, const Model& model, const Scene& scene) {
  const auto t1 = std::chrono::steady_clock::now();
  const int d = model.particles.dim;
  const std::vector<double>& u = run.u;
  RunSummary& summary = run.summary;
  std::vector<OutputField> fields;
  std::vector<double> material(model.particles.material.begin(), model.particles.material.end());
  fields.push_back({"material", 1, material});
  fields.push_back({"damage", 1, particle_damage(model.bonds)});
  std::vector<double> force(u.size());
  model.assembler->internal_forces(u.data(), force.data());
  fields.push_back({"internal_force", d, force});
  if (!run.u_smooth.empty()) fields.push_back({"smoothed_displacement", d, run.u_smooth});
  append_law_outputs(*model.assembler, model.particles, u, fields);
  if (scene.output.stress) fields.push_back({"stress", d * d, run.stress});
  const std::string dir = scene.output.directory;
  // The files form one result: when a signal stops the writing half-way, the files this
  // run already renamed into place go too (a result without its summary is partial).
  try {
    if (scene.output.vtu)
      write_vtu_file(dir + "/result.vtu", model.particles, u, fields),
          summary.files.push_back(dir + "/result.vtu");
    if (scene.output.csv)
      write_csv_file(dir + "/result.csv", model.particles, u, fields),
          summary.files.push_back(dir + "/result.csv");
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
