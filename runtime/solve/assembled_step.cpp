// The assembled Newton step: form K(u), reduce it to the free dofs, factor and solve.
#include <fmt/format.h>

#include <chrono>
#include <stdexcept>

#include "solve/linear_step.hpp"
#include "stopwatch.hpp"

namespace pd {

namespace {

class AssembledStep final : public LinearStep {
 public:
  AssembledStep(const NewtonSettings& s, bool symmetric, StepLog log)
      : linear_(s.linear, symmetric, std::move(log)) {}

  Eigen::VectorXd direction(const LinearStepInput& in, const Eigen::VectorXd& rf, NewtonRecord& rec,
                            NewtonResult& res) override {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(in.dofs.free_count());
    auto t0 = std::chrono::steady_clock::now();
    in.system.tangent(in.u, in.load, K_, nullptr);
    if (!reduced_) reduced_ = std::make_unique<ReducedSystem>(in.dofs, K_);
    reduced_->update(K_);
    res.assembly_seconds += seconds_since(t0);
    res.nonzeros = reduced_->Kff().nonZeros();
    t0 = std::chrono::steady_clock::now();
    linear_.factor(reduced_->Kff());
    const LinearSolveStats st = linear_.solve(rf, x);
    res.linear_seconds += seconds_since(t0);
    res.linear_solver = st.method;
    res.linear_choice = linear_.choice().reason;
    rec.linear_iterations = st.iterations;
    rec.linear_error = st.estimated_error;
    if (!st.converged)
      throw std::runtime_error(fmt::format("{} did not converge in {} iterations (relative residual {:.2e})",
                                           st.method, st.iterations, st.estimated_error));
    return x;
  }

 private:
  AutoLinearSolver linear_;
  SparseMatrix K_;
  std::unique_ptr<ReducedSystem> reduced_;
};
}  // namespace

std::unique_ptr<LinearStep> make_assembled_step(const NewtonSettings& settings, bool symmetric, StepLog log) {
  return std::make_unique<AssembledStep>(settings, symmetric, std::move(log));
}

}  // namespace pd
