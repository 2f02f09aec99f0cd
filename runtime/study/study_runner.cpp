// Runs the points of a study, with an on-disk cache, and writes the CSV, the order
// tables and the plots.
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fmt/core.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "input/scene.hpp"
#include "run/simulation.hpp"
#include "study/study.hpp"
#include "output/atomic_file.hpp"

namespace pd {

namespace fs = std::filesystem;

std::string StudyPoint::key() const {
  return fmt::format("{}__{}__{}__r{}__n{}", problem, law, influence, ratio, count);
}

double fit_order(const std::vector<double>& h, const std::vector<double>& e, int* used) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (!(e[i] > 0) || !std::isfinite(e[i])) continue;
    const double x = std::log(h[i]), y = std::log(e[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
  }
  if (used) *used = n;
  if (n < 2) return NAN;
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

namespace {
nlohmann::json to_json(const StudyPoint& p) {
  return {{"problem", p.problem}, {"law", p.law}, {"influence", p.influence}, {"ratio", p.ratio}, {"count", p.count},
          {"h", p.h}, {"converged", p.converged}, {"failure", p.failure}, {"error", std::isfinite(p.error) ? p.error : -1.0},
          {"particles", p.particles}, {"nonzeros", p.nonzeros}, {"setup_seconds", p.setup_seconds},
          {"assembly_seconds", p.assembly_seconds}, {"solve_seconds", p.solve_seconds}, {"total_seconds", p.total_seconds},
          {"newton_iterations", p.newton_iterations}};
}
StudyPoint from_json(const nlohmann::json& j) {
  StudyPoint p;
  p.problem = j["problem"], p.law = j["law"], p.influence = j["influence"];
  p.ratio = j["ratio"], p.count = j["count"], p.h = j["h"], p.converged = j["converged"], p.failure = j["failure"];
  p.error = j["error"].get<double>() < 0 ? NAN : j["error"].get<double>();
  p.particles = j["particles"], p.nonzeros = j["nonzeros"];
  p.setup_seconds = j["setup_seconds"], p.assembly_seconds = j["assembly_seconds"], p.solve_seconds = j["solve_seconds"];
  p.total_seconds = j["total_seconds"], p.newton_iterations = j["newton_iterations"];
  return p;
}

StudyPoint run_point(const Scene& base, const std::string& problem, const std::string& law, const std::string& influence,
                     double ratio, int count) {
  StudyPoint pt;
  pt.problem = problem, pt.law = law, pt.influence = influence;
  pt.ratio = ratio, pt.h = (base.hi[0] - base.lo[0]) / count, pt.count = count;
  Scene s = base;
  s.law = law;
  s.influence = influence;
  s.horizon_ratio = ratio;
  s.horizon_length = 0;
  s.h = pt.h;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    Simulation sim(s, [](const std::string&) {});
    const RunSummary r = sim.run(false);
    pt.converged = true;
    pt.error = r.has_field_error ? r.field_error : (r.probes.empty() ? NAN : r.probes.front().error);
    pt.particles = r.particles;
    pt.nonzeros = r.newton.nonzeros;
    pt.setup_seconds = r.setup_seconds;
    pt.assembly_seconds = r.newton.assembly_seconds;
    pt.solve_seconds = r.newton.linear_seconds;
    pt.newton_iterations = r.newton.history.empty() ? 0 : static_cast<int>(r.newton.history.size()) - 1;
  } catch (const std::exception& e) {
    pt.converged = false;
    pt.failure = e.what();
    pt.error = NAN;
  }
  pt.total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return pt;
}

template <class T>
const std::vector<T>& pick(bool quick, const std::vector<T>& full, const std::vector<T>& reduced) {
  return quick && !reduced.empty() ? reduced : full;
}
}  // namespace

std::vector<SeriesOrder> run_study(const StudySpec& spec, const std::string& out, bool quick,
                                   const std::function<void(const std::string&)>& log) {
  fs::create_directories(fs::path(out) / "points");
  std::vector<StudyPoint> points;
  const auto& laws = pick(quick, spec.laws, spec.quick_laws);
  const auto& influences = pick(quick, spec.influences, spec.quick_influences);
  const auto& ratios = pick(quick, spec.ratios, spec.quick_ratios);
  const auto& counts = pick(quick, spec.counts, spec.quick_counts);
  std::size_t total = spec.problems.size() * laws.size() * influences.size() * ratios.size() * counts.size(), done = 0;
  for (const std::string& problem_path : spec.problems) {
    const Scene base = read_scene(problem_path);
    const std::string problem = fs::path(problem_path).stem().string();
    for (const auto& law : laws)
      for (const auto& inf : influences)
        for (double ratio : ratios)
          for (int count : counts) {
            ++done;
            StudyPoint probe;
            probe.problem = problem, probe.law = law, probe.influence = inf, probe.ratio = ratio, probe.count = count;
            const fs::path cache = fs::path(out) / "points" / (probe.key() + ".json");
            StudyPoint pt;
            if (fs::exists(cache)) {
              std::ifstream in(cache);
              pt = from_json(nlohmann::json::parse(in));
            } else {
              pt = run_point(base, problem, law, inf, ratio, count);
              write_file_atomically(cache.string(), to_json(pt).dump(1));
            }
            log(fmt::format("[{}/{}] {} {} {} delta/h={} n={}: {}", done, total, problem, law, inf, ratio, count,
                            pt.converged ? fmt::format("error {:.3e}, {:.3f} s", pt.error, pt.total_seconds)
                                         : "FAILED: " + pt.failure));
            points.push_back(pt);
          }
  }
  // Series and their orders.
  std::map<std::string, std::vector<const StudyPoint*>> series;
  for (const auto& p : points) series[fmt::format("{}|{}|{}|{}", p.problem, p.law, p.influence, std::to_string(p.ratio))].push_back(&p);
  std::vector<SeriesOrder> orders;
  for (const auto& [key, pts] : series) {
    std::vector<double> h, e;
    for (const auto* p : pts) h.push_back(p->h), e.push_back(p->converged ? p->error : NAN);
    SeriesOrder o;
    o.problem = pts[0]->problem, o.law = pts[0]->law, o.influence = pts[0]->influence, o.ratio = pts[0]->ratio;
    o.order = fit_order(h, e, &o.points);
    if (auto it = spec.paper_orders.find(key); it != spec.paper_orders.end()) o.has_paper = true, o.paper = it->second;
    orders.push_back(o);
  }
  // Non-dominated points in (total time, error) per problem: the accuracy/cost frontier.
  std::set<const StudyPoint*> frontier;
  for (const auto& p : points) {
    if (!p.converged || !(p.error > 0)) continue;
    bool dominated = false;
    for (const auto& q : points)
      if (&q != &p && q.problem == p.problem && q.converged && q.error > 0 && q.error <= p.error &&
          q.total_seconds <= p.total_seconds && (q.error < p.error || q.total_seconds < p.total_seconds))
        dominated = true;
    if (!dominated) frontier.insert(&p);
  }
  std::ostringstream csv;
  csv << "problem,law,influence,ratio,count,h,converged,error,particles,nonzeros,setup_s,assembly_s,solve_s,total_s,"
         "newton_iterations,non_dominated,failure\n";
  for (const auto& p : points)
    csv << fmt::format("{},{},{},{},{},{:.9g},{},{:.9g},{},{},{:.6f},{:.6f},{:.6f},{:.6f},{},{},\"{}\"\n", p.problem, p.law,
                       p.influence, p.ratio, p.count, p.h, p.converged ? 1 : 0, p.error, p.particles, p.nonzeros,
                       p.setup_seconds, p.assembly_seconds, p.solve_seconds, p.total_seconds, p.newton_iterations,
                       frontier.count(&p) ? 1 : 0, p.failure);
  write_file_atomically((fs::path(out) / "points.csv").string(), csv.str());
  std::ostringstream md;
  md << "# Orders of convergence\n\nFitted by least squares on log e against log h (paper 000 eq. 37) from `"
     << spec.file << "`" << (quick ? " (quick sweep)" : "") << ". Paper: paper 000 Tables 3-5 where it reports the series; "
     << "**bold** marks a difference above 0.1.\n\n| problem | law | influence | delta/h | points | order | paper |\n|---|---|---|---|---|---|---|\n";
  for (const auto& o : orders) {
    const bool off = o.has_paper && std::isfinite(o.order) && std::fabs(o.order - o.paper) > 0.1;
    md << fmt::format("| {} | {} | {} | {} | {} | {}{:.3f}{} | {} |\n", o.problem, o.law, o.influence, o.ratio, o.points,
                      off ? "**" : "", o.order, off ? "**" : "", o.has_paper ? fmt::format("{:.4f}", o.paper) : "");
  }
  write_file_atomically((fs::path(out) / "orders.md").string(), md.str());
  // Plots, when matplotlib is there: Debian's python3-matplotlib for /usr/bin/python3 (scripts/install_deps.sh),
  // called by absolute path because a python3 earlier on PATH (pyenv) may not see it.
  const fs::path script = fs::path(PD_SOURCE_DIR) / "scripts" / "plot_study.py";
  if (std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0) {
    const std::string cmd = fmt::format("/usr/bin/python3 '{}' '{}'", script.string(), out);
    if (std::system(cmd.c_str()) != 0) log("plotting failed: " + cmd);
  } else {
    log("no plots: python3-matplotlib is not installed (scripts/install_deps.sh installs it)");
  }
  return orders;
}

}  // namespace pd
