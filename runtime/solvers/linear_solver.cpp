// The linear solver implementations, thin wrappers over SuiteSparse (through Eigen's
// CholmodSupport/UmfPackSupport modules) and Eigen's iterative solvers.
#include "solvers/linear_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/UmfPackSupport>
#include <stdexcept>

namespace pd {

namespace {
class Cholmod final : public LinearSolver {
 public:
  void factor(const SparseMatrix& A) override {
    if (!analysed_) {
      llt_.analyzePattern(A);
      analysed_ = true;
    }
    llt_.factorize(A);
    if (llt_.info() != Eigen::Success)
      throw std::runtime_error("CHOLMOD: the matrix is not positive definite (unconstrained rigid-body mode or unstable law?)");
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b, LinearSolveReport& r) override {
    r.method = name();
    return llt_.solve(b);
  }
  std::string name() const override { return "cholmod"; }

 private:
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt_;
  bool analysed_ = false;
};

class Umfpack final : public LinearSolver {
 public:
  void factor(const SparseMatrix& A) override {
    lu_.compute(A);
    if (lu_.info() != Eigen::Success) throw std::runtime_error("UMFPACK: the matrix is singular");
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b, LinearSolveReport& r) override {
    r.method = name();
    return lu_.solve(b);
  }
  std::string name() const override { return "umfpack"; }

 private:
  Eigen::UmfPackLU<SparseMatrix> lu_;
};

template <class Solver>
class Krylov final : public LinearSolver {
 public:
  Krylov(std::string name, double tol) : name_(std::move(name)) { solver_.setTolerance(tol); }
  void factor(const SparseMatrix& A) override {
    solver_.compute(A);
    if (solver_.info() != Eigen::Success) throw std::runtime_error(name_ + ": preconditioner construction failed");
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b, LinearSolveReport& r) override {
    Eigen::VectorXd x = solver_.solve(b);
    r.method = name_;
    r.iterations = static_cast<int>(solver_.iterations());
    r.error = solver_.error();
    if (solver_.info() != Eigen::Success)
      throw std::runtime_error(name_ + ": no convergence in " + std::to_string(r.iterations) +
                               " iterations (relative residual " + std::to_string(r.error) + ")");
    return x;
  }
  std::string name() const override { return name_; }

 private:
  std::string name_;
  Solver solver_;
};
}  // namespace

std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name, long long unknowns, bool symmetric,
                                                 double krylov_tolerance, std::string& why, long long direct_limit) {
  std::string chosen = name;
  if (name == "auto") {
    const bool direct = unknowns <= direct_limit;
    chosen = direct ? (symmetric ? "cholmod" : "umfpack") : (symmetric ? "cg" : "bicgstab");
    why = std::to_string(unknowns) + " unknowns, " + (symmetric ? "symmetric" : "non-symmetric") + " -> " + chosen +
          (direct ? " (direct below " : " (Krylov above ") + std::to_string(direct_limit) + " unknowns)";
  } else {
    why = "chosen in the scene";
  }
  if (chosen == "cholmod") return std::make_unique<Cholmod>();
  if (chosen == "umfpack") return std::make_unique<Umfpack>();
  if (chosen == "cg")
    return std::make_unique<Krylov<Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<double>>>>(
        "cg", krylov_tolerance);
  if (chosen == "bicgstab")
    return std::make_unique<Krylov<Eigen::BiCGSTAB<SparseMatrix, Eigen::IncompleteLUT<double>>>>("bicgstab", krylov_tolerance);
  throw std::invalid_argument("unknown linear solver '" + name + "'");
}

}  // namespace pd
