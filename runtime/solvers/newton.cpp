// Newton iterations on the free dofs: K_ff du = r_f, backtracking on ||r_f||.
#include "solvers/newton.hpp"

#include <chrono>
#include <cmath>
#include <fmt/core.h>
#include <stdexcept>

namespace pd {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Copies the free-free block of K (pattern fixed) through an index plan built once.
class Reduction {
 public:
  Reduction(const SparseMatrix& K, const std::vector<int>& free_index) {
    const int n = static_cast<int>(free_index.size());
    int nf = 0;
    for (int i = 0; i < n; ++i) nf += free_index[i] >= 0;
    std::vector<Eigen::Triplet<double>> t;
    for (int j = 0; j < K.outerSize(); ++j) {
      if (free_index[j] < 0) continue;
      for (SparseMatrix::InnerIterator it(K, j); it; ++it)
        if (free_index[it.row()] >= 0) t.emplace_back(free_index[it.row()], free_index[j], 0.0);
    }
    reduced_.resize(nf, nf);
    reduced_.setFromTriplets(t.begin(), t.end());
    reduced_.makeCompressed();
    // Map each kept source entry to its reduced position (same column order, rows ascending).
    for (int j = 0; j < K.outerSize(); ++j) {
      if (free_index[j] < 0) continue;
      for (SparseMatrix::InnerIterator it(K, j); it; ++it)
        if (free_index[it.row()] >= 0) source_.push_back(static_cast<int>(&it.value() - K.valuePtr()));
    }
  }
  const SparseMatrix& apply(const SparseMatrix& K) {
    double* v = reduced_.valuePtr();
    for (std::size_t i = 0; i < source_.size(); ++i) v[i] = K.valuePtr()[source_[i]];
    return reduced_;
  }

 private:
  SparseMatrix reduced_;
  std::vector<int> source_;
};
}  // namespace

NewtonReport solve_newton(const NonlinearProblem& pb, const Constraints& cons, std::vector<double>& u,
                          const NewtonOptions& opt, const std::function<void(const std::string&)>& log) {
  NewtonReport rep;
  const int n = pb.size;
  std::vector<int> free_index(static_cast<std::size_t>(n), 0);
  for (int d : cons.dofs) free_index[d] = -1;
  int nf = 0;
  for (int i = 0; i < n; ++i)
    if (free_index[i] >= 0) free_index[i] = nf++;
  rep.unknowns = nf;
  if (nf == 0) throw std::runtime_error("every degree of freedom is constrained: nothing to solve");
  auto free_norm = [&](const std::vector<double>& r) {
    double s = 0;
    for (int i = 0; i < n; ++i)
      if (free_index[i] >= 0) s += r[i] * r[i];
    return std::sqrt(s);
  };
  SparseMatrix K;
  std::vector<double> r(static_cast<std::size_t>(n)), trial(static_cast<std::size_t>(n)), r_trial;
  std::unique_ptr<LinearSolver> solver;
  std::unique_ptr<Reduction> reduction;
  for (int step = 1; step <= opt.load_steps; ++step) {
    const double load = static_cast<double>(step) / opt.load_steps;
    for (std::size_t c = 0; c < cons.dofs.size(); ++c) u[cons.dofs[c]] = load * cons.values[c];
    auto t0 = std::chrono::steady_clock::now();
    pb.stiffness(u, load, K, r);
    rep.assembly_seconds += seconds_since(t0);
    double norm = free_norm(r);
    const double scale = std::max(norm, 1e-300);
    bool step_converged = false;
    double increment = 0;
    for (int it = 0; it <= opt.max_iterations; ++it) {
      rep.history.push_back({step, it, norm, it == 0 ? 0.0 : rep.history.back().line_search, increment, 0});
      log(fmt::format("  load step {}/{}  iteration {:2d}  |r| = {:.3e}  (relative {:.3e})  |du|/|u| = {:.2e}  [{:.2f} s]",
                      step, opt.load_steps, it, norm, norm / scale, increment, rep.assembly_seconds + rep.solve_seconds));
      if (!std::isfinite(norm)) {
        rep.failure = "the residual is not finite (NaN or Inf) at load step " + std::to_string(step);
        return rep;
      }
      if (norm <= opt.tolerance * scale || norm == 0.0 || (it > 0 && increment <= opt.increment_tolerance)) {
        step_converged = true;
        break;
      }
      if (it == opt.max_iterations) break;
      if (!reduction) {
        reduction = std::make_unique<Reduction>(K, free_index);
        rep.nonzeros = K.nonZeros();
      }
      t0 = std::chrono::steady_clock::now();
      if (!solver) solver = make_linear_solver(opt.linear, nf, pb.symmetric, opt.krylov_tolerance, rep.linear_choice);
      const SparseMatrix& Kff = reduction->apply(K);
      try {
        solver->factor(Kff);
      } catch (const std::runtime_error& e) {
        if (solver->name() != "cholmod") throw;
        log(std::string("  ") + e.what() + " -- falling back to UMFPACK");
        std::string why;
        solver = make_linear_solver("umfpack", nf, false, opt.krylov_tolerance, why);
        rep.linear_choice += "; fell back to umfpack: " + std::string(e.what());
        solver->factor(Kff);
      }
      Eigen::VectorXd b(nf);
      for (int i = 0; i < n; ++i)
        if (free_index[i] >= 0) b[free_index[i]] = r[i];
      LinearSolveReport lr;
      const Eigen::VectorXd du = solver->solve(b, lr);
      rep.linear_method = lr.method;
      rep.history.back().krylov_iterations = lr.iterations;
      rep.solve_seconds += seconds_since(t0);
      // Backtracking line search on ||r_f||.
      double alpha = 1.0, trial_norm = 0;
      for (int ls = 0; ls < 12; ++ls) {
        trial = u;
        for (int i = 0; i < n; ++i)
          if (free_index[i] >= 0) trial[i] += alpha * du[free_index[i]];
        pb.residual(trial, load, r_trial);
        trial_norm = free_norm(r_trial);
        if (std::isfinite(trial_norm) && trial_norm <= (1 - 1e-4 * alpha) * norm) break;
        alpha *= 0.5;
      }
      double du2 = 0, u2 = 0;
      for (int i = 0; i < n; ++i) du2 += (trial[i] - u[i]) * (trial[i] - u[i]), u2 += trial[i] * trial[i];
      increment = u2 > 0 ? std::sqrt(du2 / u2) : 0.0;
      u = trial;
      t0 = std::chrono::steady_clock::now();
      pb.stiffness(u, load, K, r);
      rep.assembly_seconds += seconds_since(t0);
      norm = free_norm(r);
      rep.history.back().line_search = alpha;
    }
    if (!step_converged) {
      rep.failure = fmt::format("Newton did not converge at load step {} in {} iterations (|r| = {:.3e}, relative {:.3e})",
                                step, opt.max_iterations, norm, norm / scale);
      return rep;
    }
  }
  rep.converged = true;
  return rep;
}

}  // namespace pd
