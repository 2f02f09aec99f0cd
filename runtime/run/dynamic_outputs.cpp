// The dynamic run's outputs: time-series rows, checkpoints and restarts, snapshots, result files.
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "damage/critical_stretch.hpp"
#include "dynamics/checkpoint.hpp"
#include "dynamics/checkpoint_identity.hpp"
#include "dynamics/energies.hpp"
#include "dynamics/pvd_writer.hpp"
#include "effects/inertia.hpp"
#include "output/atomic_file.hpp"
#include "output/vtu_writer.hpp"
#include "run/dynamic_run.hpp"
#include "run/result_fields.hpp"
#include "run/run_outputs.hpp"
#include "stopwatch.hpp"

namespace pd {

namespace {
constexpr int kRowFixed = 7;  // step, time, kinetic, strain, external work, broken bonds, residual ratio
}  // namespace

SeriesRow DynamicRun::make_row(int step, double t, double residual_ratio) const {
  SeriesRow r;
  r.step = step;
  r.time = t;
  if (explicit_dynamics()) r.kinetic = kinetic_energy(model.inertia->mass(), v, model.dofs.free_dofs());
  if (model.assembler->has_energy()) r.strain = model.assembler->strain_energy(u.data());
  r.broken_bonds = broken_bond_count(model.bonds);
  r.residual_ratio = residual_ratio;
  const std::vector<double> stress = stress_field();
  for (std::size_t k = 0; k < probe_ids.size(); ++k)
    r.probes.push_back(probe_mean(scene.probes[k], probe_ids[k], model.particles.dim, u, &stress));
  return r;
}

std::string DynamicRun::series_csv_header() const {
  std::string h = "step,time";
  if (explicit_dynamics()) h += ",kinetic";
  if (model.assembler->has_energy()) h += ",strain";
  if (explicit_dynamics()) h += ",external_work";
  if (explicit_dynamics() && model.assembler->has_energy()) h += ",total";
  if (!explicit_dynamics()) h += ",residual_ratio";
  h += ",broken_bonds";
  for (const Probe& p : scene.probes) h += "," + p.name;
  return h + "\n";
}

std::string DynamicRun::series_csv_row(const SeriesRow& r) const {
  std::string s = fmt::format("{},{:.17g}", r.step, r.time);
  const bool inertia = explicit_dynamics(), energy = model.assembler->has_energy();
  if (inertia) s += fmt::format(",{:.17g}", r.kinetic);
  if (energy) s += fmt::format(",{:.17g}", r.strain);
  if (inertia) s += fmt::format(",{:.17g}", r.external_work);
  if (inertia && energy) s += fmt::format(",{:.17g}", r.kinetic + r.strain - r.external_work);
  if (!inertia) s += fmt::format(",{:.17g}", r.residual_ratio);
  s += fmt::format(",{}", r.broken_bonds);
  for (double p : r.probes) s += fmt::format(",{:.17g}", p);
  return s + "\n";
}

void DynamicRun::restore(const std::string& path, int& step, std::vector<double>& scalars) {
  const Checkpoint c = read_checkpoint(path);
  check_checkpoint_belongs(
      path, c, checkpoint_identity(scene, model.particles, model.bonds, explicit_dynamics() ? dt() : 0.0),
      scene.dynamics->steps);
  auto array = [&](const char* name, std::size_t size) -> const std::vector<double>& {
    const auto it = c.arrays.find(name);
    if (it == c.arrays.end() || it->second.size() != size)
      throw std::runtime_error(fmt::format(
          "{}: the checkpoint does not match this scene ({} missing or of another size)", path, name));
    return it->second;
  };
  u = array("u", u.size());
  if (!v.empty()) v = array("v", v.size());
  model.bonds.alpha = array("alpha", model.bonds.alpha.size());
  if (!model.bond_history.empty()) {
    // In place: the assembler reads the history through a pointer into this vector.
    const std::vector<double>& h = array("history", model.bond_history.size());
    std::copy(h.begin(), h.end(), model.bond_history.begin());
  }
  if (!model.particle_history.empty()) {
    const std::vector<double>& h = array("particle_history", model.particle_history.size());
    std::copy(h.begin(), h.end(), model.particle_history.begin());
  }
  scalars = c.arrays.count("scalars") ? c.arrays.at("scalars") : std::vector<double>{};
  series.clear();
  if (const auto it = c.arrays.find("series"); it != c.arrays.end()) {
    const std::size_t width = kRowFixed + scene.probes.size();
    const auto& s = it->second;
    for (std::size_t i = 0; i + width <= s.size(); i += width) {
      SeriesRow r;
      r.step = static_cast<int>(s[i]), r.time = s[i + 1], r.kinetic = s[i + 2], r.strain = s[i + 3];
      r.external_work = s[i + 4], r.broken_bonds = static_cast<long long>(s[i + 5]),
      r.residual_ratio = s[i + 6];
      r.probes.assign(s.begin() + static_cast<std::ptrdiff_t>(i + kRowFixed),
                      s.begin() + static_cast<std::ptrdiff_t>(i + width));
      series.push_back(r);
    }
  }
  snapshots.clear();
  if (const auto it = c.arrays.find("snapshots"); it != c.arrays.end())
    for (std::size_t i = 0; i + 1 < it->second.size(); i += 2)
      snapshots.emplace_back(static_cast<int>(it->second[i]), it->second[i + 1]);
  step = static_cast<int>(c.step);
  if (!model.assembler->intact()) model.assembler->update_moments();
  summary.dynamics->restarted_from = path;
  log(fmt::format("  restarted from {} at step {}", path, step));
}

void DynamicRun::save_checkpoint(int step, const std::vector<double>& scalars) {
  Checkpoint c;
  c.step = step;
  c.identity = checkpoint_identity(scene, model.particles, model.bonds, explicit_dynamics() ? dt() : 0.0);
  c.arrays["u"] = u;
  if (!v.empty()) c.arrays["v"] = v;
  c.arrays["alpha"] = model.bonds.alpha;
  if (!model.bond_history.empty()) c.arrays["history"] = model.bond_history;
  if (!model.particle_history.empty()) c.arrays["particle_history"] = model.particle_history;
  c.arrays["scalars"] = scalars;
  std::vector<double> s;
  for (const SeriesRow& r : series) {
    s.insert(s.end(), {static_cast<double>(r.step), r.time, r.kinetic, r.strain, r.external_work,
                       static_cast<double>(r.broken_bonds), r.residual_ratio});
    s.insert(s.end(), r.probes.begin(), r.probes.end());
  }
  c.arrays["series"] = std::move(s);
  std::vector<double> snaps;
  for (const auto& [st, t] : snapshots) snaps.push_back(st), snaps.push_back(t);
  c.arrays["snapshots"] = std::move(snaps);
  write_checkpoint(scene.output.directory + "/checkpoint.bin", c);
  ++summary.dynamics->checkpoints;
}

std::vector<OutputField> DynamicRun::output_fields() const {
  const std::vector<double> none;
  return result_fields({model, scene, u, v, none, none, /*dynamic=*/true});
}

std::vector<double> DynamicRun::stress_field() const {
  return wants_stress(scene) ? model.assembler->stresses(u.data()) : std::vector<double>{};
}

void DynamicRun::write_snapshot(int step, double t) {
  const std::string name = fmt::format("snapshots/step_{:08d}.vtu", step);
  write_vtu_file(scene.output.directory + "/" + name, model.particles, u, output_fields());
  if (snapshots.empty() || snapshots.back().first != step) snapshots.emplace_back(step, t);
  std::vector<PvdEntry> entries;
  for (const auto& [st, time] : snapshots)
    entries.push_back({time, fmt::format("snapshots/step_{:08d}.vtu", st)});
  write_pvd_file(scene.output.directory + "/animation.pvd", entries);
  ++summary.dynamics->snapshots;
}

RunSummary DynamicRun::finish(long long broken_start, std::chrono::steady_clock::time_point t0, bool write) {
  summary.dynamics->bonds_broken = broken_bond_count(model.bonds) - broken_start;
  summary.broken_bonds = static_cast<int>(broken_bond_count(model.bonds));
  const std::vector<double> stress = stress_field();
  summary.probes = evaluate_probes(scene, model.particles, probe_ids, u, &stress);
  summary.solve_seconds = seconds_since(t0);
  if (write) write_results();
  log(summary.text());
  return summary;
}

void DynamicRun::write_results() {
  const auto t1 = std::chrono::steady_clock::now();
  const std::string dir = scene.output.directory;
  std::string csv = series_csv_header();
  for (const SeriesRow& r : series) csv += series_csv_row(r);
  write_file_atomically(dir + "/energies.csv", csv);
  summary.files.push_back(dir + "/energies.csv");
  const auto fields = output_fields();
  write_result_files(dir, model.particles, u, fields, scene.output, summary.files);
  if (!snapshots.empty()) summary.files.push_back(dir + "/animation.pvd");
  if (summary.dynamics->checkpoints > 0) summary.files.push_back(dir + "/checkpoint.bin");
  summary.files.push_back(dir + "/summary.json");
  summary.output_seconds = seconds_since(t1);
  write_file_atomically(dir + "/summary.json", summary.json());
}

}  // namespace pd
