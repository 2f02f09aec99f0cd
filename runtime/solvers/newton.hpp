// Newton's method with backtracking line search and load stepping, on a problem given
// by callbacks, with Dirichlet conditions eliminated (the reduced system keeps the
// symmetry of the full one). Independent of peridynamics.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "solvers/linear_solver.hpp"

namespace pd {

// r(u, load) is the out-of-balance nodal force (zero at equilibrium); K = -dr/du.
struct NonlinearProblem {
  int size = 0;
  std::function<void(const std::vector<double>& u, double load, std::vector<double>& r)> residual;
  std::function<void(const std::vector<double>& u, double load, SparseMatrix& K, std::vector<double>& r)> stiffness;
  bool symmetric = true;
};

// Dirichlet conditions: value(load) of each constrained dof.
struct Constraints {
  std::vector<int> dofs;           // ascending
  std::vector<double> values;      // at full load; the value at load factor s is s * value
};

struct NewtonOptions {
  int load_steps = 1;
  double tolerance = 1e-10;  // ||r_free|| <= tolerance * scale, scale = max(||r_free(u_step_start)||, tiny)
  // ... or the last increment ||du|| <= increment_tolerance * ||u||: the residual of a
  // small-strain problem has a rounding floor near eps / strain (e = |Y| - |xi| cancels).
  double increment_tolerance = 1e-9;
  int max_iterations = 30;
  std::string linear = "auto";
  double krylov_tolerance = 1e-12;
};

struct NewtonIteration {
  int step = 0, iteration = 0;
  double residual = 0, line_search = 1;
  double increment = 0;  // ||du|| / ||u|| of the step that led here
  int krylov_iterations = 0;
};

struct NewtonReport {
  bool converged = false;
  std::vector<NewtonIteration> history;
  std::string linear_method, linear_choice;
  double assembly_seconds = 0, solve_seconds = 0;
  long long unknowns = 0, nonzeros = 0;
  std::string failure;
};

// Solves from u (in/out; constrained entries are overwritten). `log` receives one
// line per iteration.
NewtonReport solve_newton(const NonlinearProblem& problem, const Constraints& constraints, std::vector<double>& u,
                          const NewtonOptions& options, const std::function<void(const std::string&)>& log);

}  // namespace pd
