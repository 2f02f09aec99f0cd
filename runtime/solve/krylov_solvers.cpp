// Eigen's preconditioned Krylov methods on an assembled matrix: CG (IC or Jacobi), BiCGSTAB (ILUT).
#include <Eigen/IterativeLinearSolvers>

#include "solve/linear_solver.hpp"
#include "solve/progress.hpp"

namespace pd {

namespace {
template <class Solver>
class KrylovSolver final : public SparseSolver {
 public:
  KrylovSolver(std::string name, const LinearSolverOptions& o) : name_(std::move(name)) {
    solver_.setTolerance(o.tolerance);
    if (o.max_iterations > 0) solver_.setMaxIterations(o.max_iterations);
  }
  std::string name() const override { return name_; }
  // No separate analysis: compute() in factor() analyses and factors the preconditioner
  // together. Eigen 3.4's IterativeSolverBase::analyzePattern reads
  // IncompleteLUT::info() before factorize() has set it (an uninitialised enum that
  // UBSan reports, and a random success/failure otherwise).
  void analyse(const SparseMatrix&) override {}
  bool factor(const SparseMatrix& A) override {
    const ProgressPhase phase(name_ + " preconditioner of " + std::to_string(A.rows()) + " unknowns");
    solver_.compute(A);  // the preconditioner; Eigen keeps a reference to A for the products
    if (solver_.info() == Eigen::Success) return true;
    failure_ = name_ + ": the preconditioner broke down";
    return false;
  }
  LinearSolveStats solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    {
      // Eigen's loop reports no iterations until it returns: the phase shows the time.
      const ProgressPhase phase(name_ + " solve of " + std::to_string(b.size()) + " unknowns");
      x = solver_.solve(b);
    }
    LinearSolveStats s{name_, static_cast<int>(solver_.iterations()), solver_.error(),
                       solver_.info() == Eigen::Success};
    return s;
  }

 private:
  std::string name_;
  Solver solver_;
};

// Lower|Upper: the full matrix is stored, and the product with both triangles is
// faster (and parallel) than the symmetric product from one.
using CgIc =
    Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper,
                             Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>>>;
using CgDiagonal = Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper,
                                            Eigen::DiagonalPreconditioner<double>>;
using BicgstabIlut = Eigen::BiCGSTAB<SparseMatrix, Eigen::IncompleteLUT<double>>;
}  // namespace

std::unique_ptr<SparseSolver> make_krylov_solver(LinearMethod method, const LinearSolverOptions& o) {
  const Preconditioner pre = o.preconditioner;
  if (method == LinearMethod::cg) {
    if (pre == Preconditioner::automatic || pre == Preconditioner::ic)
      return std::make_unique<KrylovSolver<CgIc>>("cg+ic", o);
    if (pre == Preconditioner::diagonal) return std::make_unique<KrylovSolver<CgDiagonal>>("cg+diagonal", o);
  } else if (method == LinearMethod::bicgstab) {
    if (pre == Preconditioner::automatic || pre == Preconditioner::ilut)
      return std::make_unique<KrylovSolver<BicgstabIlut>>("bicgstab+ilut", o);
  }
  return nullptr;
}

}  // namespace pd
