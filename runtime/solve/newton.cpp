// Newton loop: per load step, solve K_ff du = r_f (a LinearStep: solve/linear_step.hpp), backtrack on |r_f|.
#include "solve/newton.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

#include "interrupt.hpp"
#include "solve/linear_step.hpp"
#include "solve/progress.hpp"
#include "stopwatch.hpp"

namespace pd {

void NonlinearSystem::jvp(const Eigen::VectorXd&, double, const Eigen::VectorXd&, Eigen::VectorXd&) {
  throw std::logic_error("this nonlinear system has no matrix-free product");
}
void NonlinearSystem::diagonal(const Eigen::VectorXd&, double, Eigen::VectorXd&) {
  throw std::logic_error("this nonlinear system has no matrix-free diagonal");
}
void NonlinearSystem::approximate_tangent(const Eigen::VectorXd&, double, SparseMatrix&) {
  throw std::logic_error("this nonlinear system has no approximate tangent");
}

// The last `window` records of this load step (iterations it-window+1 .. it) each came
// from a step of |du|/|u| <= the stagnation increment, and |r| fell by less than half
// over them.
bool NewtonSolver::stagnated(const std::vector<NewtonRecord>& history, int it) const {
  const int w = s_.stagnation_window;
  if (w <= 0 || it < w) return false;
  const std::size_t last = history.size() - 1;
  for (int k = 0; k < w; ++k)
    if (history[last - k].increment > s_.stagnation_increment) return false;
  return history[last].residual > 0.5 * history[last - w].residual;
}

// The rounding floor of |r_f| at u: how far r_f moves when u moves by as much as its own
// rounding, e_i = s_i eps (|u_i| + rounding_length) on the free dofs, with fixed
// pseudo-random signs s_i (a run stays deterministic). That is the floor of r = f_int(u)
// + f_ext as evaluated: the positions' rounding through the true stiffness (|K| eps |y|,
// the conditioning: |K||y| is far above |r_0| on a nearly incompressible or stiff-
// inclusion body) plus the two evaluations' own rounding (or noise) of the summed force
// terms; measured on r itself, so a tangent that does not match r cannot raise it. At
// least eps * reference: the applied loads are rounded too.
double NewtonSolver::rounding_floor(NonlinearSystem& sys, const DofMap& dofs, const Eigen::VectorXd& u,
                                    double load, const Eigen::VectorXd& r, double reference) const {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const double length = sys.rounding_length();
  const Eigen::VectorXd uf = dofs.restrict_free(u);
  Eigen::VectorXd ef(uf.size());
  for (Eigen::Index k = 0; k < uf.size(); ++k) {
    const std::uint64_t h = (static_cast<std::uint64_t>(k) + 1) * 0x9E3779B97F4A7C15ull;
    ef[k] = ((h >> 40) & 1 ? eps : -eps) * (std::abs(uf[k]) + length);
  }
  Eigen::VectorXd e = Eigen::VectorXd::Zero(u.size()), moved(u.size());
  dofs.expand_free(ef, e);
  sys.residual(u + e, load, moved);
  return std::max((dofs.restrict_free(moved) - dofs.restrict_free(r)).norm(), eps * reference);
}

NewtonSolver::NewtonSolver(NewtonSettings settings, std::function<void(const std::string&)> log)
    : s_(std::move(settings)), log_(std::move(log)) {
  if (s_.load_steps < 1) throw std::invalid_argument("Newton: load_steps must be at least 1");
}

namespace {

// One iteration's log line: where the solve is, |r|, the step that led here, and the time
// since the solve began.
std::string iteration_line(const NewtonSettings& s, const NewtonRecord& rec, int step, double load, int round,
                           int it, double norm, double reference,
                           std::chrono::steady_clock::time_point started) {
  return fmt::format(
      "  load {:.3g} (step {}/{}{})  iteration {:2d}  |r| = {:.3e}  relative {:.2e}{}  t = {:.1f} s", load,
      step, s.load_steps, round > 0 ? fmt::format(", re-solve {}", round) : std::string(), it, norm,
      reference > 0 ? norm / reference : 0.0,
      it == 0 ? std::string()
              : fmt::format("  step {:.3g}  |du|/|u| = {:.1e}{}", rec.step_length, rec.increment,
                            rec.linear_iterations ? fmt::format("  {} linear its", rec.linear_iterations)
                                                  : std::string()),
      seconds_since(started));
}

// Why a load step failed when its iterations ended without convergence; above_floor (when
// not empty) says why the increment or stagnation rule did not end it.
std::string not_converged_message(const NewtonSettings& s, int step, double load, int its, double norm,
                                  double reference, const std::string& above_floor) {
  return above_floor.empty()
             ? fmt::format(
                   "Newton did not converge at load {:.3g} (step {}/{}) in {} iterations: |r| = {:.3e}, "
                   "{:.2e} of the reference {:.3e} (tolerance {:.1e}); try more load steps or more "
                   "iterations",
                   load, step, s.load_steps, its, norm, reference > 0 ? norm / reference : 0.0, reference,
                   s.relative_tolerance)
             : fmt::format(
                   "Newton did not converge at load {:.3g} (step {}/{}) in {} iterations: |r| = {:.3e}, "
                   "{:.2e} of the reference {:.3e} (tolerance {:.1e}); {}",
                   load, step, s.load_steps, its, norm, reference > 0 ? norm / reference : 0.0, reference,
                   s.relative_tolerance, above_floor);
}

// What the increment and stagnation rules make of an iterate: nothing (iterate on), the
// end of the load step on the rounding floor, or repeated negligible steps above it.
enum class FloorVerdict { iterate_on, converged, stuck };

// The Newton iterations of one load step, with the state shared across load steps (the
// residual buffers and the convergence reference). The solver's private rules come in as
// callbacks.
class LoadStepIterations {
 public:
  using StagnationRule = std::function<bool(const std::vector<NewtonRecord>&, int)>;
  using FloorMeasure = std::function<double(const Eigen::VectorXd& u, double load, const Eigen::VectorXd& r,
                                            double reference)>;

  LoadStepIterations(const NewtonSettings& s, NonlinearSystem& sys, const DofMap& dofs, Eigen::VectorXd& u,
                     NewtonResult& res, LinearStep& linear_step,
                     const std::function<void(const std::string&)>& log, StagnationRule stagnated,
                     FloorMeasure rounding_floor)
      : s_(s),
        sys_(sys),
        dofs_(dofs),
        u_(u),
        res_(res),
        linear_step_(linear_step),
        log_(log),
        stagnated_(std::move(stagnated)),
        rounding_floor_(std::move(rounding_floor)),
        r_(sys.size()),
        r_trial_(sys.size()),
        trial_(sys.size()),
        du_(sys.size()),
        // Each iteration's line carries the time since the solve began: a long solve shows
        // where it is and how fast it goes (factorisations and Krylov solves are inside).
        started_(std::chrono::steady_clock::now()) {}

  // Newton iterations of one load step (round > 0: solved again after after_step
  // changed the system); false with res.message set when they fail.
  bool run(int step, double load, int round) {
    sys_.residual(u_, load, r_);
    double norm = dofs_.restrict_free(r_).norm();
    reference_ = std::max(reference_, norm);
    NewtonRecord rec{step, 0, round, load, norm, 0.0, 0.0, 0, 0.0};
    const std::size_t first = res_.history.size();  // this step's first record
    bool done = false;
    std::string above_floor;   // why the increment or stagnation rule did not end the step
    int negligible_steps = 0;  // consecutive full steps below the increment tolerance, above the ceiling
    for (int it = 0;; ++it) {
      if (interrupt_signal() != 0)
        throw_if_interrupted(
            fmt::format("during the solve (load step {}/{}, Newton iteration {})", step, s_.load_steps, it));
      rec.iteration = it;
      rec.residual = norm;
      res_.history.push_back(rec);
      say(iteration_line(s_, rec, step, load, round, it, norm, reference_, started_));
      if (!std::isfinite(norm)) {
        res_.message =
            fmt::format("Newton: the residual is not finite at load {:.3g}, iteration {}", load, it);
        return false;
      }
      if (norm <= s_.relative_tolerance * reference_ || norm <= s_.absolute_tolerance) {
        done = true;
        break;
      }
      const FloorVerdict verdict = check_floor(rec, it, load, norm, above_floor, negligible_steps);
      if (verdict == FloorVerdict::converged) {
        done = true;
        break;
      }
      if (verdict == FloorVerdict::stuck) break;
      if (it == s_.max_iterations) break;
      rec = NewtonRecord{step, it + 1, round, load, 0.0, 0.0, 0.0, 0, 0.0};
      if (!take_step(rec, it, load, norm)) return false;
    }
    if (!done) {
      const int its = res_.history.back().iteration;
      res_.message = not_converged_message(s_, step, load, its, norm, reference_, above_floor);
      say(res_.message);
      return false;
    }
    say(convergence_rate_line(first));
    return true;
  }

 private:
  void say(const std::string& line) const {
    if (log_) log_(line);
  }

  // The step's residual ratios |r_i+1| / |r_i|: under the exact (algorithmic) tangent they
  // fall like the residual itself in the last iterations (quadratic convergence); ratios
  // that stay level mean a linear rate (an inexact tangent).
  std::string convergence_rate_line(std::size_t first) const {
    std::string line = fmt::format("  converged in {} iterations", res_.history.size() - 1 - first);
    for (std::size_t i = first + 1; i < res_.history.size(); ++i)
      line += fmt::format(
          "{}{:.2e}", i == first + 1 ? "; residual ratios " : ", ",
          res_.history[i - 1].residual > 0 ? res_.history[i].residual / res_.history[i - 1].residual : 0.0);
    return line;
  }

  // The increment and stagnation rules end the step only on the rounding floor: below
  // floor_factor times the floor measured here (NewtonSettings::floor_factor).
  FloorVerdict check_floor(const NewtonRecord& rec, int it, double load, double norm,
                           std::string& above_floor, int& negligible_steps) {
    const bool small_step = it > 0 && rec.step_length == 1.0 && rec.increment <= s_.increment_tolerance;
    const bool stagnant = !small_step && stagnated_(res_.history, it);
    if (small_step || stagnant) {
      res_.rounding_floor = rounding_floor_(u_, load, r_, reference_);
      const double ceiling = s_.floor_factor * res_.rounding_floor;
      if (norm <= ceiling) {
        if (stagnant)
          say(fmt::format(
              "  stagnated on the rounding floor: |r| = {:.3e} ({:.2e} of the reference) after {} steps of "
              "|du|/|u| <= {:.0e}, within {:.0f} times the floor {:.2e}; the relative tolerance {:.0e} is "
              "below what this system's conditioning allows",
              norm, reference_ > 0 ? norm / reference_ : 0.0, s_.stagnation_window, s_.stagnation_increment,
              s_.floor_factor, res_.rounding_floor, s_.relative_tolerance));
        res_.stagnated = stagnant;
        return FloorVerdict::converged;
      }
      above_floor = fmt::format(
          "the {} (|du|/|u| = {:.1e}) with |r| = {:.3e} above the rounding-floor ceiling {:.3e} ({:.0f} "
          "times the floor {:.2e}): the tangent does not match the residual, or the system is singular or "
          "badly scaled",
          small_step ? "steps became negligible" : "iteration stagnated", rec.increment, norm, ceiling,
          s_.floor_factor, res_.rounding_floor);
      say("  " + above_floor + "; not converged, iterating on");
      // A full step that no longer moves u leaves it where it is: iterating on repeats it.
      if (small_step && ++negligible_steps == 3) return FloorVerdict::stuck;
    } else {
      negligible_steps = 0;
      above_floor.clear();
    }
    return FloorVerdict::iterate_on;
  }

  // One Newton step from iteration it: the linear direction, the line search, and the
  // move of u, r and norm to the accepted trial; false with res.message set when the
  // linear solve fails.
  bool take_step(NewtonRecord& rec, int it, double load, double& norm) {
    const Eigen::VectorXd rf = dofs_.restrict_free(r_);
    Eigen::VectorXd dx;
    try {
      dx = linear_step_.direction({sys_, dofs_, u_, load, rec.iteration, reference_}, rf, rec, res_);
    } catch (const std::runtime_error& e) {
      res_.message = fmt::format("Newton: the linear solve failed at load {:.3g}, iteration {}: {}", load,
                                 it + 1, e.what());
      return false;
    }
    du_.setZero();
    dofs_.expand_free(dx, du_);
    // A full step below the increment tolerance has converged to rounding: the residual
    // sits on its floor there, so it is taken without a line search (which could only
    // waste halvings). Otherwise backtrack: halve the step until |r_f| decreases
    // sufficiently; if none does, keep the smallest step (the next tangent may do
    // better) and say so.
    const bool negligible = du_.norm() <= s_.increment_tolerance * u_.norm();
    double trial_norm = 0.0;
    const double alpha = backtrack(load, norm, negligible, trial_norm);
    const double unorm = trial_.norm();
    rec.step_length = alpha;
    rec.increment = unorm > 0 ? alpha * du_.norm() / unorm : 0.0;
    u_ = trial_;
    r_ = r_trial_;
    norm = trial_norm;
    return true;
  }

  // The backtracking line search along du: the step length taken, with the trial point in
  // trial_, its residual in r_trial_ and |r_f| there in trial_norm.
  double backtrack(double load, double norm, bool negligible, double& trial_norm) {
    double alpha = 1.0;
    for (int b = 0;; ++b) {
      trial_ = u_ + alpha * du_;
      sys_.residual(trial_, load, r_trial_);
      trial_norm = dofs_.restrict_free(r_trial_).norm();
      if (negligible ||
          (std::isfinite(trial_norm) && trial_norm <= (1.0 - s_.sufficient_decrease * alpha) * norm))
        break;
      if (b == s_.max_backtracks) {
        say(fmt::format("  line search found no decrease after {} halvings; taking step {:.3g}", b, alpha));
        break;
      }
      alpha *= 0.5;
    }
    return alpha;
  }

  const NewtonSettings& s_;
  NonlinearSystem& sys_;
  const DofMap& dofs_;
  Eigen::VectorXd& u_;
  NewtonResult& res_;
  LinearStep& linear_step_;
  const std::function<void(const std::string&)>& log_;
  StagnationRule stagnated_;
  FloorMeasure rounding_floor_;
  Eigen::VectorXd r_, r_trial_, trial_, du_;
  double reference_ = 0;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace

NewtonResult NewtonSolver::solve(NonlinearSystem& sys, const DofMap& dofs, Eigen::VectorXd& u) {
  NewtonResult res;
  auto say = [&](const std::string& line) {
    if (log_) log_(line);
  };
  // Factorisations and Krylov solves longer than a few seconds log their progress (solve/progress.hpp).
  std::optional<ProgressSink> progress;
  if (log_) progress.emplace(log_);
  const int n = sys.size();
  if (dofs.size() != n || u.size() != n)
    throw std::invalid_argument("Newton: the system, dof map and u differ in size");
  if (dofs.free_count() == 0) throw std::invalid_argument("Newton: every degree of freedom is constrained");
  if (s_.matrix_free && !sys.has_jvp())
    throw std::invalid_argument("Newton: matrix-free solve needs the system's jvp()");

  res.unknowns = dofs.free_count();
  // Tied dofs (multipoint constraints) make the reduced tangent S K P unsymmetric.
  const bool symmetric = sys.symmetric() && dofs.keeps_symmetry();
  const std::unique_ptr<LinearStep> linear_step = s_.matrix_free
                                                      ? make_matrix_free_step(s_, sys, symmetric, log_)
                                                      : make_assembled_step(s_, symmetric, log_);
  LoadStepIterations iterations(
      s_, sys, dofs, u, res, *linear_step, log_,
      [this](const std::vector<NewtonRecord>& history, int it) { return stagnated(history, it); },
      [&](const Eigen::VectorXd& at, double load, const Eigen::VectorXd& r, double reference) {
        return rounding_floor(sys, dofs, at, load, r, reference);
      });

  // The pseudo-time from `from` (where u has converged) to `to`: iterations at the load
  // there, then after_step and re-solves while it changes the system. A first solve that
  // fails is cut: u goes back to the converged start and the two halves (in pseudo-time,
  // so a hold's halves each last half of its duration) are solved in turn (cuts_left more
  // times).
  const std::function<bool(int, double, double, int)> advance = [&](int step, double from, double to,
                                                                    int cuts_left) {
    const Eigen::VectorXd start = u;
    const double load = s_.load_at_pseudo_time(to);
    if (s_.begin_increment) s_.begin_increment(from * s_.duration, to * s_.duration);
    dofs.apply_prescribed(u, load);
    for (int round = 0;; ++round) {
      if (!iterations.run(step, load, round)) {
        if (round > 0 || cuts_left == 0) return false;
        u = start;
        ++res.step_cuts;
        const double mid = 0.5 * (from + to);
        say(fmt::format("  cutting load step {}/{}: load {:.6g} -> {:.6g}{} in two ({} more cuts allowed)",
                        step, s_.load_steps, s_.load_at_pseudo_time(from), load,
                        s_.duration > 0
                            ? fmt::format(" (time {:.6g} -> {:.6g})", from * s_.duration, to * s_.duration)
                            : std::string(),
                        cuts_left - 1));
        return advance(step, from, mid, cuts_left - 1) && advance(step, mid, to, cuts_left - 1);
      }
      if (!s_.after_step) return true;
      const long long changes = s_.after_step(step, load, u);
      if (changes == 0) return true;
      if (round == s_.max_resolves) {
        res.message = fmt::format(
            "the system still changed ({} changes) after {} re-solves of load {:.3g} (step {}/{}); try more "
            "load steps",
            changes, s_.max_resolves, load, step, s_.load_steps);
        say(res.message);
        return false;
      }
      ++res.resolves;
    }
  };
  for (int step = 1; step <= s_.load_steps; ++step) {
    const double from = static_cast<double>(step - 1) / s_.load_steps;
    const double to = static_cast<double>(step) / s_.load_steps;
    if (!advance(step, from, to, s_.max_step_cuts)) {
      if (s_.max_step_cuts > 0 && res.step_cuts > 0)
        res.message +=
            fmt::format(" (after cutting the step {} times, at most {} deep: solver.max_step_cuts)",
                        res.step_cuts, s_.max_step_cuts);
      return res;
    }
  }
  res.message.clear();  // a failure a cut recovered from
  res.converged = true;
  return res;
}

double NewtonSettings::load_at(int step) const {
  return load_at_pseudo_time(static_cast<double>(step) / load_steps);
}

double NewtonSettings::load_at_pseudo_time(double s) const {
  if (load_path.size() < 2) return s;
  const auto segments = static_cast<int>(load_path.size()) - 1;
  const double at = s * segments;
  const int k = std::min(static_cast<int>(at), segments - 1);
  const double frac = at - k;
  // Exactly the path's value at its points (step i of a multiple of the segments).
  return frac == 0.0
             ? load_path[static_cast<std::size_t>(k)]
             : load_path[static_cast<std::size_t>(k)] + frac * (load_path[static_cast<std::size_t>(k) + 1] -
                                                                load_path[static_cast<std::size_t>(k)]);
}

}  // namespace pd
