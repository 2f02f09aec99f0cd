// The factory, and AutoLinearSolver: the plan's choice on the first factorisation and
// its fallback on a failed one (both decided in solve/solver_plan.cpp).
#include <fmt/format.h>

#include <stdexcept>

#include "solve/linear_solver.hpp"

namespace pd {

std::unique_ptr<SparseSolver> make_cholmod_solver();
std::unique_ptr<SparseSolver> make_umfpack_solver();
std::unique_ptr<SparseSolver> make_krylov_solver(LinearMethod method, const LinearSolverOptions& options);

std::unique_ptr<SparseSolver> make_sparse_solver(LinearMethod method, const LinearSolverOptions& o) {
  std::unique_ptr<SparseSolver> s;
  switch (method) {
    case LinearMethod::cholmod:
      s = make_cholmod_solver();
      break;
    case LinearMethod::umfpack:
      s = make_umfpack_solver();
      break;
    case LinearMethod::cg:
    case LinearMethod::bicgstab:
      s = make_krylov_solver(method, o);
      break;
    case LinearMethod::automatic:
    case LinearMethod::matrix_free:
      break;
  }
  if (!s)
    throw std::invalid_argument(
        fmt::format("no assembled linear solver '{}' with preconditioner '{}' (methods: "
                    "cholmod, umfpack, cg [ic|diagonal], bicgstab [ilut])",
                    name_of(method), name_of(o.preconditioner)));
  return s;
}

AutoLinearSolver::AutoLinearSolver(LinearSolverOptions options, bool symmetric,
                                   std::function<void(const std::string&)> log)
    : options_(std::move(options)), symmetric_(symmetric), log_(std::move(log)) {
  if (options_.method != LinearMethod::automatic)
    solver_ = make_sparse_solver(options_.method, options_);  // fail early on a bad pair
}

void AutoLinearSolver::analyse(const SparseMatrix& A) {
  if (!chosen_) {
    choice_ = choose_linear_solver(options_.method, options_.preconditioner, options_.direct_max_nonzeros,
                                   A.rows(), A.nonZeros(), symmetric_);
    chosen_ = true;
    if (!solver_) solver_ = make_sparse_solver(choice_.method, options_);
    if (log_) log_("linear solver: " + solver_->name() + " (" + choice_.reason + ")");
  }
  solver_->analyse(A);
}

bool AutoLinearSolver::factor(const SparseMatrix& A) {
  if (!chosen_) analyse(A);
  while (!solver_->factor(A)) {
    const std::optional<SolverChoice> next = fallback_after_failure(choice_);
    if (!next) throw std::runtime_error(solver_->failure());
    const std::string why = solver_->failure();
    LinearSolverOptions o = options_;
    o.preconditioner = next->preconditioner;
    solver_ = make_sparse_solver(next->method, o);
    choice_.method = next->method;
    choice_.preconditioner = next->preconditioner;
    choice_.reason += "; fell back to " + next->reason + ": " + why;
    if (log_) log_(why + " -- falling back to " + next->reason);
    solver_->analyse(A);
  }
  return true;
}

LinearSolveStats AutoLinearSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (!solver_) throw std::logic_error("AutoLinearSolver: solve before factor");
  return solver_->solve(b, x);
}

}  // namespace pd
