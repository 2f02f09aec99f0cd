// Convergence and cost studies (paper 000 sections 5-6): every combination of problem,
// law, influence function, horizon ratio and resolution is run, its error and the wall
// time of each stage recorded; finished points are cached on disk so an interrupted
// study resumes; orders of convergence are fitted by least squares on log e against
// log h (eq. 37) and compared with the paper's tables.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pd {

// One product of laws x influences x ratios x counts. A study runs the union of its
// sweeps (a point in two sweeps runs once).
struct Sweep {
  std::vector<std::string> laws, influences;
  std::vector<double> ratios;
  std::vector<int> counts;  // particles along x
  // Influence functions to smooth each solution with (paper 000 eq. 49) before its field
  // error is measured again; scenes with a reference field only. Empty: unsmoothed only.
  std::vector<std::string> smoothing;
};

// What the paper reports for one series (problem|law|influence|ratio), or for one point
// (problem|law|influence|ratio|count): an order of convergence, the smallest error over
// the refinement, or the error of one point.
struct PaperValues {
  std::optional<double> order, min_error, error;
};

// A dynamic problem's reference: its first probe's displacement against the columns
// `time` and `value` of a CSV file (study/time_history.hpp), path relative to the study file.
struct TimeReference {
  std::string file, time = "t", value;
};

struct StudySpec {
  std::string file;
  // Dynamic problems (scenes with a dynamics section, explicit): the point's error is the
  // RMS of its first probe against this series, peak_error the largest difference.
  std::optional<TimeReference> time_reference;
  std::vector<std::string> problems;  // scene files (paths relative to the study file resolved)
  std::vector<Sweep> sweeps;          // top-level laws/influences/ratios/counts, or `sweeps:`
  // The reduced sweep of --quick: each non-empty list replaces that list in every sweep.
  Sweep quick;
  // Points whose estimated bond count, particles x pi (delta/h)^2, reaches this use the
  // matrix-free Newton-Krylov solver with the short-horizon preconditioner (0: never):
  // the direct factorisation's fill grows too fast there (gigabytes at 400^2, delta/h 3.5).
  double matrix_free_from_bonds = 0;
  // Orders are also fitted on the finest `fine_points` resolutions of each series (the
  // asymptotic order, and the paper's "data after the jagged trend begins"); 0: not.
  int fine_points = 0;
  // Replaces every problem's domain.placement (`pd study --placement`); empty: each scene's
  // own. Paper 000 places nodes on the faces; `cell` measures the same series on the
  // cell-centred lattice (docs/paper000.md section 1). Part of each point's cache key.
  std::string placement;
  // The paper's values, keyed "problem|law|influence|ratio[|count]" (problem = scene file stem).
  std::map<std::string, PaperValues> paper;
};

StudySpec read_study(const std::string& path);
// The key of StudySpec::paper: a series (count 0) or one point; `smoothing` names the
// influence function of a smoothed error (empty: the unsmoothed one).
std::string paper_key(const std::string& problem, const std::string& law, const std::string& influence,
                      double ratio, int count = 0, const std::string& smoothing = "");

struct StudyPoint {
  std::string problem, law, influence;
  double ratio = 0, h = 0;
  int count = 0;
  std::string placement;  // the override of StudySpec::placement (empty: the scene's own)
  bool converged = false;
  std::string failure;
  double error = 0;  // the first probe's error, or the field error (eq. 48) when the scene has a reference;
                     // dynamic: the RMS time-history error against StudySpec::time_reference
  double peak_error = NAN;  // dynamic: the peak time-history error (NaN for static points)
  int particles = 0;
  long long nonzeros = 0;  // of the reduced tangent; matrix-free: of the short-horizon preconditioner
  double setup_seconds = 0, assembly_seconds = 0, solve_seconds = 0, total_seconds = 0;
  int newton_iterations = 0, krylov_iterations = 0;
  std::string solver;                            // the linear method that solved the last Newton system
  double peak_rss_mb = -1;                       // peak resident memory during the point (-1: not measured)
  std::vector<std::string> smoothing;            // requested: the union over the sweeps holding the point
  std::map<std::string, double> smoothed_error;  // influence -> field error (eq. 48) of the smoothed solution
  std::string key() const;
  // The error of the solution smoothed with `smoothing`, or the unsmoothed one (empty);
  // NaN when the point failed or that smoothing was not recorded.
  double error_of(const std::string& smoothing) const;
};

// One series is one problem x law x influence x ratio, unsmoothed or smoothed with one
// influence function (`smoothing`).
struct SeriesOrder {
  std::string problem, law, influence;
  double ratio = 0;
  std::string smoothing;  // empty: the unsmoothed error
  int points = 0;
  double order = 0;       // slope of log e against log h (NaN with fewer than 2 usable points)
  double fine_order = 0;  // the same on the finest StudySpec::fine_points points (NaN if unset)
  double min_error = 0;   // the smallest error of the series (NaN if none converged)
  PaperValues paper;
};

// Runs (or loads from DIR/points/) every point, then writes DIR/points.csv, DIR/orders.md
// and, when python3 with matplotlib is available, DIR/*.png. Returns the fitted orders.
std::vector<SeriesOrder> run_study(const StudySpec& spec, const std::string& out_dir, bool quick,
                                   const std::function<void(const std::string&)>& log);

// Writes DIR/points.csv (with the non-dominated flag of the error/time frontier) and
// DIR/orders.md (orders and errors next to the paper's); returns the orders per series.
std::vector<SeriesOrder> write_study_report(const StudySpec& spec, const std::vector<StudyPoint>& points,
                                            const std::string& out_dir, bool quick);

// Least-squares slope of log(e) against log(h) over the points with e > 0.
double fit_order(const std::vector<double>& h, const std::vector<double>& e, int* used = nullptr);

}  // namespace pd
