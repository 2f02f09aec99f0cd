// The matrix-free Newton step: CG (GMRES once the system shows it is indefinite) on the
// system's tangent-vector product, never forming K, with Eisenstat-Walker forcing.
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "solve/linear_step.hpp"
#include "solve/matrix_free_krylov.hpp"
#include "stopwatch.hpp"

namespace pd {

namespace {

LinearSolverOptions direct_whatever_the_size() {
  LinearSolverOptions o;
  o.direct_max_nonzeros = std::numeric_limits<std::int64_t>::max();
  return o;
}

// The preconditioner's factorisation is not the run's linear solver: its choice is logged
// indented, under its own name, beside the driver's one "linear solver:" line.
StepLog preconditioner_log(const StepLog& log) {
  if (!log) return log;
  return [log](const std::string& line) {
    const std::string prefix = "linear solver: ";
    log("  preconditioner factor: " + (line.rfind(prefix, 0) == 0 ? line.substr(prefix.size()) : line));
  };
}

class MatrixFreeStep final : public LinearStep {
 public:
  MatrixFreeStep(const NewtonSettings& s, const NonlinearSystem& system, bool symmetric, StepLog log)
      : s_(s),
        log_(std::move(log)),
        approximate_(s.matrix_free_preconditioner == MatrixFreePreconditioner::approximate_tangent),
        P_solver_(direct_whatever_the_size(), symmetric, preconditioner_log(log_)),
        use_cg_(symmetric),
        v_full_(system.size()),
        Kv_full_(system.size()),
        diag_(system.size()) {
    if (approximate_ && !system.has_approximate_tangent())
      throw std::invalid_argument(
          "Newton: the approximate-tangent preconditioner needs the system's approximate_tangent()");
  }

  Eigen::VectorXd direction(const LinearStepInput& in, const Eigen::VectorXd& rf, NewtonRecord& rec,
                            NewtonResult& res) override {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(in.dofs.free_count());
    auto t0 = std::chrono::steady_clock::now();
    if (approximate_) {
      if (rec.iteration == 1) {  // once per load step
        in.system.approximate_tangent(in.u, in.load, P_);
        if (!reduced_P_) reduced_P_ = std::make_unique<ReducedSystem>(in.dofs, P_);
        reduced_P_->update(P_);
        res.assembly_seconds += seconds_since(t0);
        res.nonzeros = reduced_P_->Kff().nonZeros();
        t0 = std::chrono::steady_clock::now();
        P_solver_.factor(reduced_P_->Kff());
        res.linear_seconds += seconds_since(t0);
        t0 = std::chrono::steady_clock::now();
      }
    } else {
      in.system.diagonal(in.u, in.load, diag_);
      jacobi_ = diagonal_preconditioner(safe_inverse_diagonal(in.dofs.restrict_free(diag_)));
      res.assembly_seconds += seconds_since(t0);
      t0 = std::chrono::steady_clock::now();
    }
    const LinearOperator approximate_solve = [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) {
      P_solver_.solve(r, z);
    };
    const LinearOperator& precondition = approximate_ ? approximate_solve : jacobi_;
    const LinearOperator op = [&](const Eigen::VectorXd& xf, Eigen::VectorXd& yf) {
      v_full_.setZero();
      in.dofs.expand_free(xf, v_full_);
      in.system.jvp(in.u, in.load, v_full_, Kv_full_);
      yf = in.dofs.restrict_free(Kv_full_);
    };
    // CG needs K and the preconditioner positive definite: a factorisation that found
    // the approximate tangent indefinite (CHOLMOD fell back to LU) rules it out.
    if (use_cg_ && approximate_ && P_solver_.choice().method != LinearMethod::cholmod) {
      say(fmt::format("  the approximate tangent is not positive definite ({}): GMRES from here on",
                      P_solver_.name()));
      use_cg_ = false;
    }
    const double norm = rf.norm();
    const double eta = forcing(norm, rec.iteration, in.reference);
    previous_forcing_ = eta;
    KrylovResult kr;
    if (use_cg_) {
      kr = preconditioned_cg(op, precondition, rf, x, eta, s_.krylov_max_iterations);
      if (kr.indefinite) {
        // Negative curvature: the tangent is indefinite here (softening, or a follower
        // load's stiffness). GMRES does not need definiteness; restart it from zero.
        say(fmt::format(
            "  CG met negative curvature after {} iterations (the tangent is not positive definite): "
            "GMRES from here on",
            kr.iterations));
        use_cg_ = false;
        x.setZero();
      }
    }
    if (!use_cg_)
      kr = preconditioned_gmres(op, precondition, rf, x, eta, s_.gmres_restart, s_.krylov_max_iterations);
    res.linear_seconds += seconds_since(t0);
    res.linear_solver = fmt::format("matrix-free {}+{}", use_cg_ ? "cg" : "gmres",
                                    approximate_ ? P_solver_.name() : "jacobi");
    res.linear_choice = approximate_
                            ? "matrix-free Newton-Krylov preconditioned by a factorised approximate tangent"
                            : "matrix-free Newton-Krylov";
    rec.linear_iterations = kr.iterations;
    rec.linear_error = kr.relative_residual;
    if (!kr.converged)
      throw std::runtime_error(fmt::format("{} did not converge in {} iterations (relative residual {:.2e})",
                                           res.linear_solver, kr.iterations, kr.relative_residual));
    previous_norm_ = norm;
    return x;
  }

 private:
  void say(const std::string& line) const {
    if (log_) log_(line);
  }
  // The Krylov tolerance of this Newton step: Eisenstat-Walker choice 2 (gamma 0.9,
  // exponent 2), or krylov_tolerance when adaptive forcing is off.
  double forcing(double norm, int iteration, double reference) const {
    if (!s_.adaptive_forcing) return s_.krylov_tolerance;
    double eta = s_.max_forcing;
    if (iteration > 1 && previous_norm_ > 0) {
      eta = 0.9 * std::pow(norm / previous_norm_, 2);
      const double safeguard = 0.9 * previous_forcing_ * previous_forcing_;
      if (safeguard > 0.1) eta = std::max(eta, safeguard);
    }
    // No tighter than what brings |r| to the tolerance, nor than krylov_tolerance.
    eta = std::min(eta, s_.max_forcing);
    eta = std::max(eta, 0.5 * s_.relative_tolerance * reference / std::max(norm, 1e-300));
    return std::max(eta, s_.krylov_tolerance);
  }

  NewtonSettings s_;
  StepLog log_;
  bool approximate_;
  SparseMatrix P_;
  std::unique_ptr<ReducedSystem> reduced_P_;
  AutoLinearSolver P_solver_;  // a direct factorisation of P, whatever its size
  LinearOperator jacobi_;
  bool use_cg_;  // CG until the system shows it is indefinite
  double previous_norm_ = 0, previous_forcing_ = 0;
  Eigen::VectorXd v_full_, Kv_full_, diag_;
};
}  // namespace

std::unique_ptr<LinearStep> make_matrix_free_step(const NewtonSettings& settings,
                                                  const NonlinearSystem& system, bool symmetric,
                                                  StepLog log) {
  return std::make_unique<MatrixFreeStep>(settings, system, symmetric, std::move(log));
}

}  // namespace pd
