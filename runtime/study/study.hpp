// Convergence and cost studies (paper 000 sections 5-6): every combination of problem,
// law, influence function, horizon ratio and resolution is run, its error and the wall
// time of each stage recorded; finished points are cached on disk so an interrupted
// study resumes; orders of convergence are fitted by least squares on log e against
// log h (eq. 37) and compared with the paper's tables.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace pd {

struct StudySpec {
  std::string file;
  std::vector<std::string> problems;  // scene files (paths relative to the study file resolved)
  std::vector<std::string> laws, influences;
  std::vector<double> ratios;
  std::vector<int> counts;            // particles along x
  // The reduced sweep of --quick (any list left empty keeps the full one).
  std::vector<std::string> quick_laws, quick_influences;
  std::vector<double> quick_ratios;
  std::vector<int> quick_counts;
  // The paper's orders, keyed "problem|law|influence|ratio" (problem = scene file stem).
  std::map<std::string, double> paper_orders;
};

StudySpec read_study(const std::string& path);

struct StudyPoint {
  std::string problem, law, influence;
  double ratio = 0, h = 0;
  int count = 0;
  bool converged = false;
  std::string failure;
  double error = 0;  // the first probe's error, or the field error (eq. 48) when the scene has a reference
  int particles = 0;
  long long nonzeros = 0;
  double setup_seconds = 0, assembly_seconds = 0, solve_seconds = 0, total_seconds = 0;
  int newton_iterations = 0;
  std::string key() const;
};

struct SeriesOrder {
  std::string problem, law, influence;
  double ratio = 0;
  int points = 0;
  double order = 0;  // slope of log e against log h (NaN with fewer than 2 usable points)
  bool has_paper = false;
  double paper = 0;
};

// Runs (or loads from DIR/points/) every point, then writes DIR/points.csv, DIR/orders.md
// and, when python3 with matplotlib is available, DIR/*.png. Returns the fitted orders.
std::vector<SeriesOrder> run_study(const StudySpec& spec, const std::string& out_dir, bool quick,
                                   const std::function<void(const std::string&)>& log);

// Least-squares slope of log(e) against log(h) over the points with e > 0.
double fit_order(const std::vector<double>& h, const std::vector<double>& e, int* used = nullptr);

}  // namespace pd
