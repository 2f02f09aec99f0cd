// Newton loop: per load step, solve K_ff du = r_f (direct/Krylov or matrix-free), backtrack on |r_f|.
#include "solve/newton.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "interrupt.hpp"
#include "solve/matrix_free_krylov.hpp"

namespace pd {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

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

NewtonSolver::NewtonSolver(NewtonSettings settings, std::function<void(const std::string&)> log)
    : s_(std::move(settings)), log_(std::move(log)) {
  if (s_.load_steps < 1) throw std::invalid_argument("Newton: load_steps must be at least 1");
}

NewtonResult NewtonSolver::solve(NonlinearSystem& sys, const DofMap& dofs, Eigen::VectorXd& u) {
  NewtonResult res;
  auto say = [&](const std::string& line) {
    if (log_) log_(line);
  };
  const int n = sys.size();
  if (dofs.size() != n || u.size() != n) throw std::invalid_argument("Newton: the system, dof map and u differ in size");
  if (dofs.free_count() == 0) throw std::invalid_argument("Newton: every degree of freedom is constrained");
  if (s_.matrix_free && !sys.has_jvp()) throw std::invalid_argument("Newton: matrix-free solve needs the system's jvp()");

  res.unknowns = dofs.free_count();
  SparseMatrix K;
  std::unique_ptr<ReducedSystem> reduced;
  AutoLinearSolver linear(s_.linear, sys.symmetric(), log_);
  Eigen::VectorXd r(n), r_trial(n), trial(n), du(n), v_full(n), Kv_full(n), diag(n);
  // The matrix-free preconditioner: Jacobi, or a factorised approximate tangent.
  if (s_.matrix_free && s_.matrix_free_preconditioner != "diagonal" && s_.matrix_free_preconditioner != "approximate")
    throw std::invalid_argument("Newton: unknown matrix-free preconditioner '" + s_.matrix_free_preconditioner + "'");
  const bool approximate = s_.matrix_free && s_.matrix_free_preconditioner == "approximate";
  if (approximate && !sys.has_approximate_tangent())
    throw std::invalid_argument("Newton: the approximate-tangent preconditioner needs the system's approximate_tangent()");
  SparseMatrix P;
  std::unique_ptr<ReducedSystem> reduced_P;
  LinearSolverOptions p_options;  // a direct factorisation, whatever its size
  p_options.direct_max_nonzeros = std::numeric_limits<std::int64_t>::max();
  AutoLinearSolver P_solver(p_options, sys.symmetric(), log_);
  LinearOperator jacobi;
  const LinearOperator approximate_solve = [&](const Eigen::VectorXd& rf, Eigen::VectorXd& z) { P_solver.solve(rf, z); };
  double reference = 0;
  bool use_cg = sys.symmetric();  // matrix-free: CG until the system shows it is indefinite

  // Newton step on the free dofs: K_ff du_f = r_f (du_c = 0: the constrained values
  // were already set at the start of the load step).
  // The Krylov tolerance of this Newton step (matrix-free path).
  double previous_norm = 0, previous_forcing = 0;
  auto forcing = [&](double norm, int iteration) {
    if (!s_.adaptive_forcing) return s_.krylov_tolerance;
    double eta = s_.max_forcing;
    if (iteration > 1 && previous_norm > 0) {
      eta = 0.9 * std::pow(norm / previous_norm, 2);
      const double safeguard = 0.9 * previous_forcing * previous_forcing;
      if (safeguard > 0.1) eta = std::max(eta, safeguard);
    }
    // No tighter than what brings |r| to the tolerance, nor than krylov_tolerance.
    eta = std::min(eta, s_.max_forcing);
    eta = std::max(eta, 0.5 * s_.relative_tolerance * reference / std::max(norm, 1e-300));
    return std::max(eta, s_.krylov_tolerance);
  };
  auto newton_direction = [&](const Eigen::VectorXd& rf, double load, NewtonRecord& rec) -> Eigen::VectorXd {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(dofs.free_count());
    if (!s_.matrix_free) {
      auto t0 = std::chrono::steady_clock::now();
      sys.tangent(u, load, K, nullptr);
      if (!reduced) reduced = std::make_unique<ReducedSystem>(dofs, K);
      reduced->update(K);
      res.assembly_seconds += seconds_since(t0);
      res.nonzeros = reduced->Kff().nonZeros();
      t0 = std::chrono::steady_clock::now();
      linear.factor(reduced->Kff());
      const LinearSolveStats st = linear.solve(rf, x);
      res.linear_seconds += seconds_since(t0);
      res.linear_solver = st.method;
      res.linear_choice = linear.choice().reason;
      rec.linear_iterations = st.iterations;
      rec.linear_error = st.estimated_error;
      if (!st.converged)
        throw std::runtime_error(fmt::format("{} did not converge in {} iterations (relative residual {:.2e})", st.method,
                                             st.iterations, st.estimated_error));
      return x;
    }
    auto t0 = std::chrono::steady_clock::now();
    if (approximate) {
      if (rec.iteration == 1) {  // once per load step
        sys.approximate_tangent(u, load, P);
        if (!reduced_P) reduced_P = std::make_unique<ReducedSystem>(dofs, P);
        reduced_P->update(P);
        res.assembly_seconds += seconds_since(t0);
        res.nonzeros = reduced_P->Kff().nonZeros();
        t0 = std::chrono::steady_clock::now();
        P_solver.factor(reduced_P->Kff());
        res.linear_seconds += seconds_since(t0);
        t0 = std::chrono::steady_clock::now();
      }
    } else {
      sys.diagonal(u, load, diag);
      jacobi = diagonal_preconditioner(safe_inverse_diagonal(dofs.restrict_free(diag)));
      res.assembly_seconds += seconds_since(t0);
      t0 = std::chrono::steady_clock::now();
    }
    const LinearOperator& precondition = approximate ? approximate_solve : jacobi;
    const LinearOperator op = [&](const Eigen::VectorXd& xf, Eigen::VectorXd& yf) {
      v_full.setZero();
      dofs.expand_free(xf, v_full);
      sys.jvp(u, load, v_full, Kv_full);
      yf = dofs.restrict_free(Kv_full);
    };
    // CG needs K and the preconditioner positive definite: a factorisation that found
    // the approximate tangent indefinite (CHOLMOD fell back to LU) rules it out.
    if (use_cg && approximate && P_solver.name() != "cholmod") {
      say(fmt::format("  the approximate tangent is not positive definite ({}): GMRES from here on", P_solver.name()));
      use_cg = false;
    }
    const double eta = forcing(rf.norm(), rec.iteration);
    previous_forcing = eta;
    KrylovResult kr;
    if (use_cg) {
      kr = preconditioned_cg(op, precondition, rf, x, eta, s_.krylov_max_iterations);
      if (kr.indefinite) {
        // Negative curvature: the tangent is indefinite here (softening, or a follower
        // load's stiffness). GMRES does not need definiteness; restart it from zero.
        say(fmt::format("  CG met negative curvature after {} iterations (the tangent is not positive definite): "
                        "GMRES from here on", kr.iterations));
        use_cg = false;
        x.setZero();
      }
    }
    if (!use_cg)
      kr = preconditioned_gmres(op, precondition, rf, x, eta, s_.gmres_restart, s_.krylov_max_iterations);
    res.linear_seconds += seconds_since(t0);
    res.linear_solver = fmt::format("matrix-free {}+{}", use_cg ? "cg" : "gmres", approximate ? P_solver.name() : "jacobi");
    res.linear_choice = approximate ? "matrix-free Newton-Krylov preconditioned by a factorised approximate tangent"
                                    : "matrix-free Newton-Krylov";
    rec.linear_iterations = kr.iterations;
    rec.linear_error = kr.relative_residual;
    if (!kr.converged)
      throw std::runtime_error(fmt::format("{} did not converge in {} iterations (relative residual {:.2e})",
                                           res.linear_solver, kr.iterations, kr.relative_residual));
    return x;
  };

  // Newton iterations of one load step (round > 0: solved again after after_step
  // changed the system); false with res.message set when they fail.
  auto iterate = [&](int step, double load, int round) -> bool {
    sys.residual(u, load, r);
    double norm = dofs.restrict_free(r).norm();
    reference = std::max(reference, norm);
    NewtonRecord rec{step, 0, round, load, norm, 0.0, 0.0, 0, 0.0};
    bool done = false;
    for (int it = 0;; ++it) {
      if (interrupt_signal() != 0)
        throw_if_interrupted(fmt::format("during the solve (load step {}/{}, Newton iteration {})", step, s_.load_steps, it));
      rec.iteration = it;
      rec.residual = norm;
      res.history.push_back(rec);
      say(fmt::format(
          "  load {:.3g} (step {}/{}{})  iteration {:2d}  |r| = {:.3e}  relative {:.2e}{}", load, step,
          s_.load_steps, round > 0 ? fmt::format(", re-solve {}", round) : std::string(), it, norm,
          reference > 0 ? norm / reference : 0.0,
          it == 0 ? std::string()
                  : fmt::format("  step {:.3g}  |du|/|u| = {:.1e}{}", rec.step_length, rec.increment,
                                rec.linear_iterations ? fmt::format("  {} linear its", rec.linear_iterations)
                                                      : std::string())));
      if (!std::isfinite(norm)) {
        res.message =
            fmt::format("Newton: the residual is not finite at load {:.3g}, iteration {}", load, it);
        return false;
      }
      if (norm <= s_.relative_tolerance * reference || norm <= s_.absolute_tolerance ||
          (it > 0 && rec.step_length == 1.0 && rec.increment <= s_.increment_tolerance)) {
        done = true;
        break;
      }
      if (stagnated(res.history, it)) {
        res.stagnated = done = true;
        say(fmt::format(
            "  stagnated on the rounding floor: |r| = {:.3e} ({:.2e} of the reference) after {} steps of "
            "|du|/|u| <= {:.0e}; the relative tolerance {:.0e} is below what this system's conditioning "
            "allows",
            norm, reference > 0 ? norm / reference : 0.0, s_.stagnation_window, s_.stagnation_increment,
            s_.relative_tolerance));
        break;
      }
      if (it == s_.max_iterations) break;
      rec = NewtonRecord{step, it + 1, round, load, 0.0, 0.0, 0.0, 0, 0.0};
      const Eigen::VectorXd rf = dofs.restrict_free(r);
      Eigen::VectorXd dx;
      try {
        dx = newton_direction(rf, load, rec);
        previous_norm = norm;
      } catch (const std::runtime_error& e) {
        res.message = fmt::format("Newton: the linear solve failed at load {:.3g}, iteration {}: {}", load,
                                  it + 1, e.what());
        return false;
      }
      du.setZero();
      dofs.expand_free(dx, du);
      // A full step below the increment tolerance has converged to rounding: the residual
      // sits on its floor there, so it is taken without a line search (which could only
      // waste halvings). Otherwise backtrack: halve the step until |r_f| decreases
      // sufficiently; if none does, keep the smallest step (the next tangent may do
      // better) and say so.
      const bool negligible = du.norm() <= s_.increment_tolerance * u.norm();
      double alpha = 1.0, trial_norm = 0.0;
      for (int b = 0;; ++b) {
        trial = u + alpha * du;
        sys.residual(trial, load, r_trial);
        trial_norm = dofs.restrict_free(r_trial).norm();
        if (negligible ||
            (std::isfinite(trial_norm) && trial_norm <= (1.0 - s_.sufficient_decrease * alpha) * norm))
          break;
        if (b == s_.max_backtracks) {
          say(fmt::format("  line search found no decrease after {} halvings; taking step {:.3g}", b, alpha));
          break;
        }
        alpha *= 0.5;
      }
      const double unorm = trial.norm();
      rec.step_length = alpha;
      rec.increment = unorm > 0 ? alpha * du.norm() / unorm : 0.0;
      u = trial;
      r = r_trial;
      norm = trial_norm;
    }
    if (!done) {
      res.message = fmt::format(
          "Newton did not converge at load {:.3g} (step {}/{}) in {} iterations: |r| = {:.3e}, {:.2e} of the "
          "reference {:.3e} (tolerance {:.1e}); try more load steps or more iterations",
          load, step, s_.load_steps, s_.max_iterations, norm, reference > 0 ? norm / reference : 0.0,
          reference, s_.relative_tolerance);
      say(res.message);
      return false;
    }
    return true;
  };

  for (int step = 1; step <= s_.load_steps; ++step) {
    const double load = static_cast<double>(step) / s_.load_steps;
    dofs.apply_prescribed(u, load);
    for (int round = 0;; ++round) {
      if (!iterate(step, load, round)) return res;
      if (!s_.after_step) break;
      const long long changes = s_.after_step(step, load, u);
      if (changes == 0) break;
      if (round == s_.max_resolves) {
        res.message = fmt::format(
            "the system still changed ({} changes) after {} re-solves of load {:.3g} (step {}/{}); try more load steps",
            changes, s_.max_resolves, load, step, s_.load_steps);
        say(res.message);
        return res;
      }
      ++res.resolves;
    }
  }
  res.converged = true;
  return res;
}

}  // namespace pd
