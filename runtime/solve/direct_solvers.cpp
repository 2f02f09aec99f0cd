// CHOLMOD (supernodal Cholesky) and UMFPACK (LU) through Eigen's SuiteSparse wrappers.
#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>
#include <string>

#include "solve/linear_solver.hpp"
#include "solve/progress.hpp"

namespace pd {

namespace {
class CholmodSolver final : public SparseSolver {
 public:
  CholmodSolver() {
    // CHOLMOD prints its own warning for a non-positive-definite matrix; the caller
    // reports the failure (and the fallback) in the run log instead.
    llt_.cholmod().print = 0;
  }
  std::string name() const override { return std::string(name_of(LinearMethod::cholmod)); }
  void analyse(const SparseMatrix& A) override {
    llt_.analyzePattern(A);
    analysed_ = true;
  }
  bool factor(const SparseMatrix& A) override {
    if (!analysed_) analyse(A);
    {
      const ProgressPhase phase("CHOLMOD factorisation of " + std::to_string(A.rows()) + " unknowns");
      llt_.factorize(A);
    }
    if (llt_.info() == Eigen::Success) return true;
    failure_ =
        "CHOLMOD: the matrix is not positive definite (a rigid-body mode left unconstrained, a "
        "non-symmetric law, or a law that lost stability?)";
    return false;
  }
  LinearSolveStats solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    x = llt_.solve(b);
    return {name(), 0, 0.0, true};
  }

 private:
  // Lower: CHOLMOD reads one triangle of the symmetric matrix.
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt_;
  bool analysed_ = false;
};

// UMFPACK's 64-bit-index interface (umfpack_dl_*), on a copy of the matrix with long
// indices: the 32-bit one (umfpack_di_*) bounds its work space by INT_MAX and reported
// "out of memory" for paper 001's 256^2 collocation system at 4 GB resident with 19 GB free.
// The same algorithm and ordering, so the same factors; the copy costs 12 bytes a nonzero.
using LongSparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, SuiteSparse_long>;

class UmfpackSolver final : public SparseSolver {
 public:
  std::string name() const override { return std::string(name_of(LinearMethod::umfpack)); }
  void analyse(const SparseMatrix& A) override {
    long_ = A;
    lu_.analyzePattern(long_);
    analysed_ = true;
  }
  bool factor(const SparseMatrix& A) override {
    if (!analysed_)
      analyse(A);  // copies A
    else
      long_ = A;  // the new values (same pattern); UMFPACK's solve reads the matrix again
    {
      const ProgressPhase phase("UMFPACK factorisation of " + std::to_string(A.rows()) + " unknowns");
      lu_.factorize(long_);
    }
    if (lu_.info() == Eigen::Success) return true;
    // Eigen reports every failure alike; UMFPACK's status says which it was (an
    // out-of-memory once passed for a singular matrix in the run log).
    const int status = lu_.umfpackFactorizeReturncode();
    failure_ = status == UMFPACK_WARNING_singular_matrix
                   ? "UMFPACK: the matrix is singular (an unconstrained rigid-body mode?)"
               : status == UMFPACK_ERROR_out_of_memory
                   ? "UMFPACK: out of memory in the numeric factorisation"
                   : "UMFPACK: the numeric factorisation failed with status " + std::to_string(status);
    return false;
  }
  LinearSolveStats solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    x = lu_.solve(b);
    return {name(), 0, 0.0, true};
  }

 private:
  LongSparseMatrix long_;
  Eigen::UmfPackLU<LongSparseMatrix> lu_;
  bool analysed_ = false;
};
}  // namespace

std::unique_ptr<SparseSolver> make_cholmod_solver() { return std::make_unique<CholmodSolver>(); }
std::unique_ptr<SparseSolver> make_umfpack_solver() { return std::make_unique<UmfpackSolver>(); }

}  // namespace pd
