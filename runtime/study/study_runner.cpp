// Runs the points of a study, with an on-disk cache, then the report and the plots.
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>

#include "input/scene.hpp"
#include "kernel_abi.hpp"
#include "output/atomic_file.hpp"
#include "post/smoothing.hpp"
#include "run/dynamic_simulation.hpp"
#include "run/simulation.hpp"
#include "study/installed_data.hpp"
#include "study/peak_memory.hpp"
#include "study/study.hpp"
#include "study/time_history.hpp"

namespace pd {

namespace fs = std::filesystem;

std::string StudyPoint::key() const {
  const std::string key = fmt::format("{}__{}__{}__r{}__n{}", problem, law, influence, ratio, count);
  return placement.empty() ? key : key + "__" + placement;
}

double StudyPoint::error_of(const std::string& smoothing_influence) const {
  if (smoothing_influence.empty()) return error;
  const auto it = smoothed_error.find(smoothing_influence);
  return converged && it != smoothed_error.end() ? it->second : NAN;
}

namespace {
nlohmann::json to_json(const StudyPoint& p) {
  return {{"problem", p.problem},
          {"law", p.law},
          {"influence", p.influence},
          {"ratio", p.ratio},
          {"count", p.count},
          {"placement", p.placement},
          {"h", p.h},
          {"converged", p.converged},
          {"failure", p.failure},
          {"error", std::isfinite(p.error) ? p.error : -1.0},
          {"particles", p.particles},
          {"nonzeros", p.nonzeros},
          {"setup_seconds", p.setup_seconds},
          {"assembly_seconds", p.assembly_seconds},
          {"solve_seconds", p.solve_seconds},
          {"total_seconds", p.total_seconds},
          {"newton_iterations", p.newton_iterations},
          {"krylov_iterations", p.krylov_iterations},
          {"solver", p.solver},
          {"peak_rss_mb", p.peak_rss_mb},
          {"smoothed_error", p.smoothed_error},
          {"peak_error", std::isfinite(p.peak_error) ? p.peak_error : -1.0}};
}
StudyPoint from_json(const nlohmann::json& j) {
  StudyPoint p;
  p.problem = j["problem"], p.law = j["law"], p.influence = j["influence"];
  p.placement = j.value("placement", std::string());
  p.ratio = j["ratio"], p.count = j["count"], p.h = j["h"], p.converged = j["converged"],
  p.failure = j["failure"];
  p.error = j["error"].get<double>() < 0 ? NAN : j["error"].get<double>();
  p.particles = j["particles"], p.nonzeros = j["nonzeros"];
  p.setup_seconds = j["setup_seconds"], p.assembly_seconds = j["assembly_seconds"],
  p.solve_seconds = j["solve_seconds"];
  p.total_seconds = j["total_seconds"], p.newton_iterations = j["newton_iterations"];
  // Points cached before these were recorded keep their defaults (unknown).
  p.krylov_iterations = j.value("krylov_iterations", 0);
  p.solver = j.value("solver", std::string());
  p.peak_rss_mb = j.value("peak_rss_mb", -1.0);
  p.peak_error = j.value("peak_error", -1.0) < 0 ? NAN : j["peak_error"].get<double>();
  if (j.contains("smoothed_error"))
    p.smoothed_error = j["smoothed_error"].get<std::map<std::string, double>>();
  return p;
}

// A dynamic point (paper 003 section 5.1): the run's first probe against the study's
// time_reference, RMS and peak relative to the reference's largest magnitude.
void dynamic_point(const Scene& s, const StudySpec& spec, StudyPoint& pt) {
  if (!spec.time_reference)
    throw std::runtime_error(
        "a dynamic problem needs the study's time_reference: {file, time, value} to be measured against");
  if (s.dynamics->method != DynamicsMethod::explicit_verlet)
    throw std::runtime_error("a relaxation problem has no time history; study it as a static scene");
  if (s.probes.empty())
    throw std::runtime_error("a dynamic problem needs a probe: its first probe is measured");
  const TimeSeries ref =
      read_time_series(spec.time_reference->file, spec.time_reference->time, spec.time_reference->value);
  DynamicSimulation sim(s, [](const std::string&) {});
  const RunSummary r = sim.run(false);
  std::vector<double> t, v;
  for (const SeriesRow& row : sim.series()) {
    t.push_back(row.time);
    v.push_back(row.probes.at(0));
  }
  const TimeHistoryError e = time_history_error(t, v, ref);
  pt.converged = true;
  pt.error = e.rms;
  pt.peak_error = e.peak;
  pt.particles = r.particles;
  pt.setup_seconds = r.setup_seconds;
  pt.solve_seconds = r.solve_seconds;
  pt.solver = "explicit";
}

StudyPoint run_point(const Scene& base, const StudySpec& spec, const StudyPoint& id) {
  StudyPoint pt = id;
  pt.h = (base.hi[0] - base.lo[0]) / id.count;
  Scene s = base;
  s.law = id.law;
  s.influence = id.influence;
  s.horizon_ratio = id.ratio;
  s.horizon_length = 0;
  s.h = pt.h;
  if (!id.placement.empty()) s.placement = parse_name<Placement>(id.placement).value_or(Placement::cell);
  // Estimated bonds: particles (from the box, before holes) x the lattice sites in a disc of radius delta/h.
  double particles = 1;
  for (int c = 0; c < s.dim; ++c) particles *= (s.hi[c] - s.lo[c]) / s.h;
  if (spec.matrix_free_from_bonds > 0 &&
      particles * std::numbers::pi * id.ratio * id.ratio >= spec.matrix_free_from_bonds) {
    s.solver.linear = LinearMethod::matrix_free;
    s.solver.preconditioner = Preconditioner::short_horizon;
  }
  const bool measured = reset_peak_memory();
  const auto t0 = std::chrono::steady_clock::now();
  try {
    if (s.dynamics) {
      dynamic_point(s, spec, pt);
      pt.total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (measured) pt.peak_rss_mb = peak_memory_mb();
      return pt;
    }
    Simulation sim(s, [](const std::string&) {});
    const RunSummary r = sim.run(false);
    pt.converged = true;
    pt.error = r.has_field_error ? r.field_error : (r.probes.empty() ? NAN : r.probes.front().error);
    pt.particles = r.particles;
    pt.nonzeros = r.newton.nonzeros;
    pt.setup_seconds = r.setup_seconds;
    pt.assembly_seconds = r.newton.assembly_seconds;
    pt.solve_seconds = r.newton.linear_seconds;
    pt.newton_iterations = r.newton.iterations();
    for (const auto& rec : r.newton.history) pt.krylov_iterations += rec.linear_iterations;
    pt.solver = r.newton.linear_solver;
    // Eq. (49) with each requested influence, on the intact bonds of the law's own horizon.
    for (const std::string& name : id.smoothing) {
      const abi::InfluenceDescriptor* w = abi::find_influence(name);
      const auto u_s = smooth_field(sim.particles(), sim.bonds(), w->weight, sim.displacement(), s.dim);
      pt.smoothed_error[name] = sim.reference_error(u_s);
    }
  } catch (const std::exception& e) {
    pt.converged = false;
    pt.failure = e.what();
    pt.error = NAN;
  }
  pt.total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (measured) pt.peak_rss_mb = peak_memory_mb();
  return pt;
}

// A point's cost in arbitrary units for the ETA: its bonds, particles x (delta/h)^dim.
// Direct factorisations grow faster than that, so the ETA is a lower bound early on.
double point_cost(const Scene& scene, const StudyPoint& p) {
  const double particles = std::pow(p.count, scene.dim), neighbours = std::pow(p.ratio, scene.dim);
  return particles * neighbours;
}

std::string eta_text(double seconds) {
  if (seconds < 120) return fmt::format("ETA {:.0f} s", seconds);
  if (seconds < 7200) return fmt::format("ETA {:.1f} min", seconds / 60);
  return fmt::format("ETA {:.1f} h", seconds / 3600);
}

template <class T>
const std::vector<T>& pick(bool quick, const std::vector<T>& full, const std::vector<T>& reduced) {
  return quick && !reduced.empty() ? reduced : full;
}

// The points of every sweep for one problem, in sweep order, each once (with the union
// of the smoothings its sweeps ask for).
std::vector<StudyPoint> plan(const StudySpec& spec, const std::string& problem, bool quick) {
  std::vector<StudyPoint> out;
  std::map<std::string, std::size_t> seen;
  for (const Sweep& w : spec.sweeps)
    for (const auto& law : pick(quick, w.laws, spec.quick.laws))
      for (const auto& inf : pick(quick, w.influences, spec.quick.influences))
        for (double ratio : pick(quick, w.ratios, spec.quick.ratios))
          for (int count : pick(quick, w.counts, spec.quick.counts)) {
            StudyPoint p;
            p.problem = problem, p.law = law, p.influence = inf, p.ratio = ratio, p.count = count;
            p.placement = spec.placement;
            const auto [it, added] = seen.emplace(p.key(), out.size());
            if (added) out.push_back(p);
            for (const auto& name : pick(quick, w.smoothing, spec.quick.smoothing)) {
              auto& wanted = out[it->second].smoothing;
              if (std::find(wanted.begin(), wanted.end(), name) == wanted.end()) wanted.push_back(name);
            }
          }
  return out;
}

// A cached point serves when it holds every smoothed error the study now asks for.
bool has_smoothings(const StudyPoint& cached, const StudyPoint& wanted) {
  for (const auto& name : wanted.smoothing)
    if (cached.converged && !cached.smoothed_error.count(name)) return false;
  return true;
}
}  // namespace

std::vector<SeriesOrder> run_study(const StudySpec& spec, const std::string& out, bool quick,
                                   const std::function<void(const std::string&)>& log) {
  fs::create_directories(fs::path(out) / "points");
  // Every scene is read before the first point runs (read_study checked that the scenes
  // of smoothed sweeps have a reference field).
  struct Problem {
    std::string path;
    Scene scene;
    std::vector<StudyPoint> todo;
  };
  std::vector<Problem> problems;
  std::size_t total = 0, done = 0;
  for (const std::string& path : spec.problems) {
    problems.push_back({path, read_scene(path), plan(spec, fs::path(path).stem().string(), quick)});
    total += problems.back().todo.size();
  }
  // The ETA: seconds per unit of estimated cost, measured on the points run so far (not
  // the cached ones), times the cost still to come.
  std::map<const StudyPoint*, double> cost;
  double cost_left = 0, cost_run = 0, seconds_run = 0;
  for (const Problem& problem : problems)
    for (const StudyPoint& id : problem.todo) cost_left += cost[&id] = point_cost(problem.scene, id);
  std::vector<StudyPoint> points;
  for (const Problem& problem : problems) {
    for (const StudyPoint& id : problem.todo) {
      ++done;
      cost_left -= cost[&id];
      const fs::path cache = fs::path(out) / "points" / (id.key() + ".json");
      StudyPoint pt;
      bool cached = false;
      if (fs::exists(cache)) {
        std::ifstream in(cache);
        pt = from_json(nlohmann::json::parse(in));
        cached = has_smoothings(pt, id);
      }
      if (!cached) {
        pt = run_point(problem.scene, spec, id);
        write_file_atomically(cache.string(), to_json(pt).dump(1));
        cost_run += cost[&id];
        seconds_run += pt.total_seconds;
      }
      const std::string eta =
          cost_run > 0 && done < total ? ", " + eta_text(seconds_run / cost_run * cost_left) : "";
      pt.smoothing = id.smoothing;
      std::string smoothed;
      for (const auto& name : pt.smoothing)
        smoothed += fmt::format(", smoothed ({}) {:.3e}", name, pt.error_of(name));
      log(fmt::format("[{}/{}] {} {} {} delta/h={} n={}: {}", done, total, pt.problem, pt.law, pt.influence,
                      pt.ratio, pt.count,
                      pt.converged ? fmt::format("error {:.3e}{}, {:.3f} s, {}", pt.error, smoothed,
                                                 pt.total_seconds, pt.solver)
                                   : "FAILED: " + pt.failure) +
          eta);
      points.push_back(pt);
    }
  }
  const auto orders = write_study_report(spec, points, out, quick);
  // Plots, when matplotlib is there: Debian's python3-matplotlib for /usr/bin/python3
  // (scripts/install_deps.sh), called by absolute path because a python3 earlier on PATH (pyenv) may not see
  // it. The script ships beside pd (share/pdgen/, build and installed trees alike), not in a source checkout
  // that may be gone.
  const fs::path script = installed_data_file("plot_study.py");
  if (!fs::exists(script)) {
    log("no plots: " + script.string() + " is missing (it is installed beside pd, in ../share/pdgen/)");
  } else if (std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0) {
    const std::string cmd = fmt::format("/usr/bin/python3 '{}' '{}'", script.string(), out);
    if (std::system(cmd.c_str()) != 0) log("plotting failed: " + cmd);
  } else {
    log("no plots: python3-matplotlib is not installed (scripts/install_deps.sh installs it)");
  }
  return orders;
}

}  // namespace pd
