// The linear solve of one Newton step, K(u) dx = r_f on the free dofs, behind one
// interface: Newton (solve/newton.cpp) keeps load steps, line search and convergence;
// a step type owns its matrices, solvers and state between Newton iterations.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>

#include "constraints/dof_map.hpp"
#include "solve/newton.hpp"

namespace pd {

// What a step sees of the Newton iteration it serves.
struct LinearStepInput {
  NonlinearSystem& system;
  const DofMap& dofs;
  const Eigen::VectorXd& u;  // the current iterate (all dofs)
  double load;               // the load factor of the load step
  int iteration;             // the Newton iteration this step leads to (1 for the first of a load step)
  double reference;          // the largest initial |r_f| so far (the convergence reference)
};

class LinearStep {
 public:
  virtual ~LinearStep() = default;
  // The Newton direction on the free dofs for the right-hand side rf = r_f(u). Fills
  // rec's linear_iterations and linear_error, and res's timings, nonzeros and
  // linear_solver / linear_choice. Throws std::runtime_error when the solve fails.
  virtual Eigen::VectorXd direction(const LinearStepInput& in, const Eigen::VectorXd& rf, NewtonRecord& rec,
                                    NewtonResult& res) = 0;
};

using StepLog = std::function<void(const std::string&)>;

// Assembled tangent, reduced to the free dofs, solved by the plan's sparse solver: a
// direct factorisation (solve/direct_solvers.cpp) or a preconditioned Krylov method
// (solve/krylov_solvers.cpp), with the fallbacks of AutoLinearSolver.
std::unique_ptr<LinearStep> make_assembled_step(const NewtonSettings& settings, bool symmetric, StepLog log);

// Matrix-free Newton-Krylov (solve/matrix_free_step.cpp): CG or GMRES on the system's
// jvp, preconditioned by Jacobi or by the factorised approximate tangent. Throws
// std::invalid_argument when the system lacks what the preconditioner needs.
// `symmetric`: the reduced tangent is (the system's, and no tied dofs).
std::unique_ptr<LinearStep> make_matrix_free_step(const NewtonSettings& settings,
                                                  const NonlinearSystem& system, bool symmetric, StepLog log);

}  // namespace pd
