// The automatic solver rule, the factory, and the fallback on a failed factorisation.
#include <fmt/format.h>

#include <stdexcept>

#include "solve/linear_solver.hpp"

namespace pd {

std::unique_ptr<SparseSolver> make_cholmod_solver();
std::unique_ptr<SparseSolver> make_umfpack_solver();
std::unique_ptr<SparseSolver> make_krylov_solver(const std::string& method, const LinearSolverOptions& options);

SolverChoice choose_linear_solver(const LinearSolverOptions& o, std::int64_t unknowns, std::int64_t nonzeros,
                                  bool symmetric) {
  if (o.method != "auto") return {o.method, "named in the options"};
  const bool direct = nonzeros <= o.direct_max_nonzeros;
  const std::string method = direct ? (symmetric ? "cholmod" : "umfpack") : (symmetric ? "cg" : "bicgstab");
  return {method, fmt::format("{} unknowns, {} nonzeros, {} -> {} ({} {} nonzeros)", unknowns, nonzeros,
                              symmetric ? "symmetric" : "non-symmetric", method, direct ? "direct up to" : "Krylov above",
                              o.direct_max_nonzeros)};
}

std::unique_ptr<SparseSolver> make_sparse_solver(const std::string& method, const LinearSolverOptions& o) {
  if (method == "cholmod") return make_cholmod_solver();
  if (method == "umfpack") return make_umfpack_solver();
  if (auto s = make_krylov_solver(method, o)) return s;
  throw std::invalid_argument("unknown linear solver '" + method + "' with preconditioner '" + o.preconditioner +
                              "' (methods: auto, cholmod, umfpack, cg [ic|diagonal], bicgstab [ilut])");
}

AutoLinearSolver::AutoLinearSolver(LinearSolverOptions options, bool symmetric, std::function<void(const std::string&)> log)
    : options_(std::move(options)), symmetric_(symmetric), log_(std::move(log)) {
  if (options_.method != "auto") solver_ = make_sparse_solver(options_.method, options_);  // fail early on a bad name
}

void AutoLinearSolver::analyse(const SparseMatrix& A) {
  if (choice_.method.empty()) {
    choice_ = choose_linear_solver(options_, A.rows(), A.nonZeros(), symmetric_);
    if (!solver_) solver_ = make_sparse_solver(choice_.method, options_);
    if (log_) log_("linear solver: " + solver_->name() + " (" + choice_.reason + ")");
  }
  solver_->analyse(A);
}

bool AutoLinearSolver::factor(const SparseMatrix& A) {
  if (choice_.method.empty()) analyse(A);
  while (!solver_->factor(A)) {
    std::string next;
    if (solver_->name() == "cholmod") next = "umfpack";
    else if (solver_->name() == "cg+ic") next = "cg+diagonal";
    if (next.empty()) throw std::runtime_error(solver_->failure());
    const std::string why = solver_->failure();
    LinearSolverOptions o = options_;
    if (next == "cg+diagonal") o.preconditioner = "diagonal";
    solver_ = make_sparse_solver(next == "umfpack" ? "umfpack" : "cg", o);
    choice_.reason += "; fell back to " + next + ": " + why;
    if (log_) log_(why + " -- falling back to " + next);
    solver_->analyse(A);
  }
  return true;
}

LinearSolveStats AutoLinearSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (!solver_) throw std::logic_error("AutoLinearSolver: solve before factor");
  return solver_->solve(b, x);
}

}  // namespace pd
