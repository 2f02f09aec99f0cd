// The study's report: orders of convergence per series (eq. 37), the error/time frontier,
// points.csv and orders.md with the paper's values alongside.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "output/atomic_file.hpp"
#include "study/study.hpp"

namespace pd {

namespace fs = std::filesystem;

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
std::string number(const std::optional<double>& v, const char* format) {
  return v ? fmt::format(fmt::runtime(format), *v) : "";
}
std::string memory(double mb) { return mb < 0 ? "" : fmt::format("{:.0f}", mb); }

// Non-dominated points in (total time, error) per problem: the accuracy/cost frontier.
std::set<const StudyPoint*> frontier(const std::vector<StudyPoint>& points) {
  std::set<const StudyPoint*> out;
  for (const auto& p : points) {
    if (!p.converged || !(p.error > 0)) continue;
    bool dominated = false;
    for (const auto& q : points)
      if (&q != &p && q.problem == p.problem && q.converged && q.error > 0 && q.error <= p.error &&
          q.total_seconds <= p.total_seconds && (q.error < p.error || q.total_seconds < p.total_seconds))
        dominated = true;
    if (!dominated) out.insert(&p);
  }
  return out;
}
void add_once(std::vector<std::string>& list, const std::string& name) {
  if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
}

// The orders and smallest error of one series (points sorted coarse to fine), unsmoothed
// or with one smoothing; points that lack that smoothing are left out.
SeriesOrder fit_series(const StudySpec& spec, const std::vector<const StudyPoint*>& pts,
                       const std::string& smoothing) {
  std::vector<double> h, e;
  for (const auto* p : pts) {
    const double v = p->error_of(smoothing);
    if (smoothing.empty() || std::isfinite(v)) h.push_back(p->h), e.push_back(v);
  }
  SeriesOrder o;
  o.problem = pts[0]->problem, o.law = pts[0]->law, o.influence = pts[0]->influence, o.ratio = pts[0]->ratio;
  o.smoothing = smoothing;
  o.order = fit_order(h, e, &o.points);
  o.fine_order = NAN;
  if (spec.fine_points >= 2 && static_cast<int>(h.size()) > spec.fine_points) {
    const std::size_t from = h.size() - static_cast<std::size_t>(spec.fine_points);
    o.fine_order = fit_order({h.begin() + from, h.end()}, {e.begin() + from, e.end()});
  }
  o.min_error = NAN;
  for (double v : e)
    if (v > 0 && !(v >= o.min_error)) o.min_error = v;
  if (auto it = spec.paper.find(paper_key(o.problem, o.law, o.influence, o.ratio, 0, smoothing));
      it != spec.paper.end())
    o.paper = it->second;
  return o;
}

// Points grouped by series: the series keys in first-seen order and each series' points.
using SeriesMap = std::map<std::string, std::vector<const StudyPoint*>>;
void group_series(const std::vector<StudyPoint>& points, std::vector<std::string>& keys, SeriesMap& series) {
  for (const auto& p : points) {
    const std::string key = paper_key(p.problem, p.law, p.influence, p.ratio);
    if (!series.count(key)) keys.push_back(key);
    series[key].push_back(&p);
  }
}

// Fits each series once unsmoothed, then once per smoothing its points recorded; collects
// every smoothing seen (first-seen order) for the columns of points.csv.
std::vector<SeriesOrder> fit_all_series(const StudySpec& spec, const std::vector<std::string>& keys,
                                        SeriesMap& series, std::vector<std::string>& all_smoothings) {
  std::vector<SeriesOrder> orders;
  for (const auto& key : keys) {
    auto pts = series[key];
    std::sort(pts.begin(), pts.end(), [](auto* a, auto* b) { return a->h > b->h; });
    std::vector<std::string> smoothings{""};
    for (const auto* p : pts)
      for (const auto& name : p->smoothing) add_once(smoothings, name), add_once(all_smoothings, name);
    for (const auto& smoothing : smoothings) orders.push_back(fit_series(spec, pts, smoothing));
  }
  return orders;
}

// The text of points.csv: one row per point, with the frontier flag and a column per smoothing.
std::string points_csv(const std::vector<StudyPoint>& points,
                       const std::vector<std::string>& all_smoothings) {
  const auto best = frontier(points);
  std::ostringstream csv;
  csv << "problem,law,influence,ratio,count,h,converged,error,particles,nonzeros,setup_s,assembly_s,solve_s,"
         "total_s,"
         "newton_iterations,krylov_iterations,solver,peak_rss_mb,non_dominated,failure,peak_error";
  for (const auto& name : all_smoothings) csv << ",error_smoothed_" << name;  // empty where not recorded
  csv << "\n";
  for (const auto& p : points) {
    csv << fmt::format(
        "{},{},{},{},{},{:.9g},{},{:.9g},{},{},{:.6f},{:.6f},{:.6f},{:.6f},{},{},\"{}\",{:.1f},{},\"{}\"",
        p.problem, p.law, p.influence, p.ratio, p.count, p.h, p.converged ? 1 : 0, p.error, p.particles,
        p.nonzeros, p.setup_seconds, p.assembly_seconds, p.solve_seconds, p.total_seconds,
        p.newton_iterations, p.krylov_iterations, p.solver, p.peak_rss_mb, best.count(&p) ? 1 : 0, p.failure);
    csv << (std::isfinite(p.peak_error) ? fmt::format(",{:.9g}", p.peak_error)
                                        : std::string(","));  // dynamic points
    for (const auto& name : all_smoothings) {
      const double v = p.error_of(name);
      csv << (std::isfinite(v) ? fmt::format(",{:.9g}", v) : std::string(","));
    }
    csv << "\n";
  }
  return csv.str();
}

// orders.md's heading and its table of fitted orders next to the paper's.
void write_orders_table(std::ostringstream& md, const StudySpec& spec, const std::vector<SeriesOrder>& orders,
                        bool quick) {
  md << "# Orders of convergence\n\nFitted by least squares on log e against log h (paper 000 eq. 37) from `"
     << spec.file << "`" << (quick ? " (quick sweep)" : "") << "; `fine` fits the finest " << spec.fine_points
     << " resolutions only. Paper: paper 000's tables where it reports the series; **bold** marks an order "
        "more than "
        "0.1 from the paper's.\n\n"
        "| problem | law | influence | delta/h | smoothed | points | order | fine | min error | paper order "
        "| paper min error |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& o : orders) {
    const bool off = o.paper.order && std::isfinite(o.order) && std::fabs(o.order - *o.paper.order) > 0.1;
    md << fmt::format("| {} | {} | {} | {} | {} | {} | {}{:.3f}{} | {} | {} | {} | {} |\n", o.problem, o.law,
                      o.influence, o.ratio, o.smoothing.empty() ? "no" : o.smoothing, o.points,
                      off ? "**" : "", o.order, off ? "**" : "",
                      std::isfinite(o.fine_order) ? fmt::format("{:.3f}", o.fine_order) : "",
                      std::isfinite(o.min_error) ? fmt::format("{:.4g}", o.min_error) : "",
                      number(o.paper.order, "{:.4f}"), number(o.paper.min_error, "{:.3f}"));
  }
}

// Single points the paper reports (e.g. its Table 7) next to ours; nothing when it reports none.
void write_single_points(std::ostringstream& md, const StudySpec& spec,
                         const std::vector<StudyPoint>& points) {
  std::ostringstream single;
  for (const auto& p : points) {
    std::vector<std::string> smoothings{""};
    smoothings.insert(smoothings.end(), p.smoothing.begin(), p.smoothing.end());
    for (const auto& smoothing : smoothings)
      if (auto it = spec.paper.find(paper_key(p.problem, p.law, p.influence, p.ratio, p.count, smoothing));
          it != spec.paper.end() && it->second.error)
        single << fmt::format("| {} | {} | {} | {} | {} | {} | {:.4g} | {:.4f} |\n", p.problem, p.law,
                              p.influence, p.ratio, p.count, smoothing.empty() ? "no" : smoothing,
                              p.error_of(smoothing), *it->second.error);
  }
  if (!single.str().empty())
    md << "\n## Errors of single points\n\n| problem | law | influence | delta/h | n | smoothed | error | "
          "paper |\n"
          "|---|---|---|---|---|---|---|---|\n"
       << single.str();
}

// What the finest point of each series cost, and which solver reached it.
void write_finest_cost(std::ostringstream& md, const std::vector<std::string>& keys, SeriesMap& series) {
  md << "\n## Cost of the finest point of each series\n\n| problem | law | influence | delta/h | n | "
        "particles | "
        "solver | Newton | Krylov | nonzeros | seconds | peak MiB "
        "|\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& key : keys) {
    const auto& pts = series[key];
    const StudyPoint* p =
        *std::max_element(pts.begin(), pts.end(), [](auto* a, auto* b) { return a->count < b->count; });
    md << fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {:.1f} | {} |\n", p->problem,
                      p->law, p->influence, p->ratio, p->count, p->particles,
                      p->converged ? p->solver : "FAILED", p->newton_iterations, p->krylov_iterations,
                      p->nonzeros, p->total_seconds, memory(p->peak_rss_mb));
  }
}
}  // namespace

std::vector<SeriesOrder> write_study_report(const StudySpec& spec, const std::vector<StudyPoint>& points,
                                            const std::string& out, bool quick) {
  // Series (in first-seen order) and their orders.
  std::vector<std::string> keys;
  SeriesMap series;
  group_series(points, keys, series);
  std::vector<std::string> all_smoothings;
  std::vector<SeriesOrder> orders = fit_all_series(spec, keys, series, all_smoothings);
  write_file_atomically((fs::path(out) / "points.csv").string(), points_csv(points, all_smoothings));

  std::ostringstream md;
  write_orders_table(md, spec, orders, quick);
  write_single_points(md, spec, points);
  write_finest_cost(md, keys, series);
  write_file_atomically((fs::path(out) / "orders.md").string(), md.str());
  return orders;
}

}  // namespace pd
