// The dynamic run's outputs: time-series rows, checkpoints and restarts, snapshots, result files.
#include "run/dynamic_simulation.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>

#include "discretize/discretization.hpp"
#include "discretize/family_quality.hpp"
#include "model/model.hpp"
#include "dynamics/checkpoint.hpp"
#include "dynamics/checkpoint_identity.hpp"
#include "dynamics/dynamic_relaxation.hpp"
#include "dynamics/energies.hpp"
#include "dynamics/progress.hpp"
#include "dynamics/pvd_writer.hpp"
#include "dynamics/time_step.hpp"
#include "dynamics/verlet_integrator.hpp"
#include "fields/analytic.hpp"
#include "input/yaml_keys.hpp"
#include "interrupt.hpp"
#include "output/atomic_file.hpp"
#include "output/csv_writer.hpp"
#include "output/vtu_writer.hpp"
#include "post/peridynamic_stress.hpp"
#include "run/constraints.hpp"
#include "run/run_outputs.hpp"
#include "solve/stopwatch.hpp"

namespace pd {

namespace {
constexpr int kRowFixed = 7;  // step, time, kinetic, strain, external work, broken bonds, residual ratio
}  // namespace

SeriesRow DynamicSimulation::make_row(int step, double t, double residual_ratio) const {
  SeriesRow r;
  r.step = step;
  r.time = t;
  if (!mass_.empty()) r.kinetic = kinetic_energy(mass_, v_, free_);
  if (model_.assembler->has_energy()) r.strain = model_.assembler->strain_energy(u_.data());
  r.broken_bonds = broken_bond_count(model_.bonds);
  r.residual_ratio = residual_ratio;
  const std::vector<double> stress = stress_field();
  for (std::size_t k = 0; k < probe_ids_.size(); ++k)
    r.probes.push_back(probe_mean(scene_.probes[k], probe_ids_[k], model_.particles.dim, u_, &stress));
  return r;
}

std::string DynamicSimulation::series_csv_header() const {
  std::string h = "step,time";
  if (!mass_.empty()) h += ",kinetic";
  if (model_.assembler->has_energy()) h += ",strain";
  if (!mass_.empty()) h += ",external_work";
  if (!mass_.empty() && model_.assembler->has_energy()) h += ",total";
  if (mass_.empty()) h += ",residual_ratio";
  h += ",broken_bonds";
  for (const Probe& p : scene_.probes) h += "," + p.name;
  return h + "\n";
}

std::string DynamicSimulation::series_csv_row(const SeriesRow& r) const {
  std::string s = fmt::format("{},{:.17g}", r.step, r.time);
  const bool inertia = !mass_.empty(), energy = model_.assembler->has_energy();
  if (inertia) s += fmt::format(",{:.17g}", r.kinetic);
  if (energy) s += fmt::format(",{:.17g}", r.strain);
  if (inertia) s += fmt::format(",{:.17g}", r.external_work);
  if (inertia && energy) s += fmt::format(",{:.17g}", r.kinetic + r.strain - r.external_work);
  if (!inertia) s += fmt::format(",{:.17g}", r.residual_ratio);
  s += fmt::format(",{}", r.broken_bonds);
  for (double p : r.probes) s += fmt::format(",{:.17g}", p);
  return s + "\n";
}

void DynamicSimulation::restore(const std::string& path, int& step, std::vector<double>& scalars) {
  const Checkpoint c = read_checkpoint(path);
  check_checkpoint_belongs(path, c, checkpoint_identity(scene_, model_.particles, model_.bonds, mass_.empty() ? 0.0 : dt_), scene_.dynamics->steps);
  auto array = [&](const char* name, std::size_t size) -> const std::vector<double>& {
    const auto it = c.arrays.find(name);
    if (it == c.arrays.end() || it->second.size() != size)
      throw std::runtime_error(fmt::format("{}: the checkpoint does not match this scene ({} missing or of another size)", path, name));
    return it->second;
  };
  u_ = array("u", u_.size());
  if (!v_.empty()) v_ = array("v", v_.size());
  model_.bonds.alpha = array("alpha", model_.bonds.alpha.size());
  scalars = c.arrays.count("scalars") ? c.arrays.at("scalars") : std::vector<double>{};
  series_.clear();
  if (const auto it = c.arrays.find("series"); it != c.arrays.end()) {
    const std::size_t width = kRowFixed + scene_.probes.size();
    const auto& s = it->second;
    for (std::size_t i = 0; i + width <= s.size(); i += width) {
      SeriesRow r;
      r.step = static_cast<int>(s[i]), r.time = s[i + 1], r.kinetic = s[i + 2], r.strain = s[i + 3];
      r.external_work = s[i + 4], r.broken_bonds = static_cast<long long>(s[i + 5]), r.residual_ratio = s[i + 6];
      r.probes.assign(s.begin() + static_cast<std::ptrdiff_t>(i + kRowFixed), s.begin() + static_cast<std::ptrdiff_t>(i + width));
      series_.push_back(r);
    }
  }
  snapshots_.clear();
  if (const auto it = c.arrays.find("snapshots"); it != c.arrays.end())
    for (std::size_t i = 0; i + 1 < it->second.size(); i += 2) snapshots_.emplace_back(static_cast<int>(it->second[i]), it->second[i + 1]);
  step = static_cast<int>(c.step);
  if (!model_.assembler->intact()) model_.assembler->update_moments();
  summary_.dynamics->restarted_from = path;
  log_(fmt::format("  restarted from {} at step {}", path, step));
}

void DynamicSimulation::save_checkpoint(int step, const std::vector<double>& scalars) {
  Checkpoint c;
  c.step = step;
  c.identity = checkpoint_identity(scene_, model_.particles, model_.bonds, mass_.empty() ? 0.0 : dt_);
  c.arrays["u"] = u_;
  if (!v_.empty()) c.arrays["v"] = v_;
  c.arrays["alpha"] = model_.bonds.alpha;
  c.arrays["scalars"] = scalars;
  std::vector<double> s;
  for (const SeriesRow& r : series_) {
    s.insert(s.end(), {static_cast<double>(r.step), r.time, r.kinetic, r.strain, r.external_work,
                       static_cast<double>(r.broken_bonds), r.residual_ratio});
    s.insert(s.end(), r.probes.begin(), r.probes.end());
  }
  c.arrays["series"] = std::move(s);
  std::vector<double> snaps;
  for (const auto& [st, t] : snapshots_) snaps.push_back(st), snaps.push_back(t);
  c.arrays["snapshots"] = std::move(snaps);
  write_checkpoint(scene_.output.directory + "/checkpoint.bin", c);
  ++summary_.dynamics->checkpoints;
}

std::vector<OutputField> DynamicSimulation::output_fields() const {
  std::vector<OutputField> fields;
  if (!v_.empty()) fields.push_back({"velocity", model_.particles.dim, v_});
  fields.push_back({"material", 1, std::vector<double>(model_.particles.material.begin(), model_.particles.material.end())});
  if (model_.damage || !model_.assembler->intact()) fields.push_back({"damage", 1, particle_damage(model_.bonds)});
  append_law_outputs(*model_.assembler, model_.particles, u_, fields);
  if (scene_.output.stress) fields.push_back({"stress", model_.particles.dim * model_.particles.dim, stress_field()});
  return fields;
}

std::vector<double> DynamicSimulation::stress_field() const {
  return wants_stress(scene_) ? peridynamic_stress(*model_.assembler, u_.data()) : std::vector<double>{};
}

void DynamicSimulation::write_snapshot(int step, double t) {
  const std::string name = fmt::format("snapshots/step_{:08d}.vtu", step);
  write_vtu_file(scene_.output.directory + "/" + name, model_.particles, u_, output_fields());
  if (snapshots_.empty() || snapshots_.back().first != step) snapshots_.emplace_back(step, t);
  std::vector<PvdEntry> entries;
  for (const auto& [st, time] : snapshots_) entries.push_back({time, fmt::format("snapshots/step_{:08d}.vtu", st)});
  write_pvd_file(scene_.output.directory + "/animation.pvd", entries);
  ++summary_.dynamics->snapshots;
}

void DynamicSimulation::write_results() {
  const auto t1 = std::chrono::steady_clock::now();
  const std::string dir = scene_.output.directory;
  std::string csv = series_csv_header();
  for (const SeriesRow& r : series_) csv += series_csv_row(r);
  write_file_atomically(dir + "/energies.csv", csv);
  summary_.files.push_back(dir + "/energies.csv");
  const auto fields = output_fields();
  if (scene_.output.vtu) write_vtu_file(dir + "/result.vtu", model_.particles, u_, fields), summary_.files.push_back(dir + "/result.vtu");
  if (scene_.output.csv) write_csv_file(dir + "/result.csv", model_.particles, u_, fields), summary_.files.push_back(dir + "/result.csv");
  if (!snapshots_.empty()) summary_.files.push_back(dir + "/animation.pvd");
  if (summary_.dynamics->checkpoints > 0) summary_.files.push_back(dir + "/checkpoint.bin");
  summary_.files.push_back(dir + "/summary.json");
  summary_.output_seconds = seconds_since(t1);
  write_file_atomically(dir + "/summary.json", summary_.json());
}


}  // namespace pd
