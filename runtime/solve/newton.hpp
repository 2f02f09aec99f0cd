// Newton's method with backtracking line search and load stepping, assembled or matrix-free.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "assembly/sparsity_pattern.hpp"
#include "constraints/dof_map.hpp"
#include "solve/linear_solver.hpp"

namespace pd {

// The problem, as callbacks: nothing here knows about peridynamics. `load` is the load
// factor in (0, 1] of the current load step; the system scales its external loads by
// it (prescribed displacements are scaled by the solver through the DofMap).
class NonlinearSystem {
 public:
  virtual ~NonlinearSystem() = default;
  virtual int size() const = 0;
  // Out-of-balance force r(u) = f_internal(u) + load * f_external: zero at equilibrium.
  virtual void residual(const Eigen::VectorXd& u, double load, Eigen::VectorXd& r) = 0;
  // K = -dr/du with a pattern that does not change between calls; also r when r is
  // not null (one assembly pass gives both).
  virtual void tangent(const Eigen::VectorXd& u, double load, SparseMatrix& K, Eigen::VectorXd* r) = 0;
  virtual bool symmetric() const { return true; }
  // Matrix-free Newton-Krylov needs these two: Kv = K(u) v and the diagonal of K(u).
  virtual bool has_jvp() const { return false; }
  virtual void jvp(const Eigen::VectorXd& u, double load, const Eigen::VectorXd& v, Eigen::VectorXd& Kv);
  virtual void diagonal(const Eigen::VectorXd& u, double load, Eigen::VectorXd& d);
  // A sparser matrix close to K(u) (e.g. the same law on a shorter horizon), whose
  // factorisation preconditions the matrix-free path; fixed pattern between calls.
  virtual bool has_approximate_tangent() const { return false; }
  virtual void approximate_tangent(const Eigen::VectorXd& u, double load, SparseMatrix& P);
  // The length each unknown is rounded against inside r: a peridynamic bond's deformed
  // vector Y = xi + (u_q - u_p) is held to eps |xi|, not eps |u|, so a small-strain
  // residual's rounding floor is set by the bond lengths (PeridynamicSystem: the largest
  // horizon). 0: the unknowns are rounded only against themselves. Newton's rounding
  // floor (NewtonSettings::floor_factor) perturbs u by eps (|u_i| + this).
  virtual double rounding_length() const { return 0.0; }
};

// The matrix-free path's preconditioner: Jacobi (from NonlinearSystem::diagonal) or a
// direct factorisation of NonlinearSystem::approximate_tangent.
enum class MatrixFreePreconditioner { jacobi, approximate_tangent };

struct NewtonSettings {
  int load_steps = 1;
  // The load factor along the steps (solver.load_path): values at the equally spaced
  // pseudo-times 0, 1/K, ..., 1 of its K segments, linear between; load step i solves at
  // the factor at i / load_steps. Empty: proportional loading, factor i / load_steps.
  std::vector<double> load_path;
  double load_at(int step) const;
  // The factor at pseudo-time s in [0, 1] (load step i ends at s = i / load_steps).
  double load_at_pseudo_time(double s) const;
  // solver.duration: the physical time the whole path takes, for a rate-dependent law
  // (viscoelastic): pseudo-time s is t = s * duration, so a load step lasts duration /
  // load_steps, a hold (a flat stretch of load_path) lets the law relax, and a cut step's
  // halves last half as long each. 0: no physical time (every increment lasts 0).
  double duration = 0.0;
  // Called before the iterations of every increment (a load step, or a part of a cut one)
  // with its physical start and end times, so the system integrates a rate-dependent law
  // over end - start (run/static_run.cpp sets the model's step duration). A re-solve after
  // after_step changed the system repeats the same increment.
  std::function<void(double t_start, double t_end)> begin_increment;
  int max_iterations = 25;  // per load step
  // solver.max_step_cuts: a load step whose iterations fail (not converged, a residual
  // that is not finite, a failed linear solve) is solved again from the step's converged
  // start in two halves, each cut again if it fails, down to 2^-max_step_cuts of the step.
  // after_step (history commits, damage) sees only the halves that converged. 0: a failed
  // step ends the solve.
  int max_step_cuts = 0;
  double relative_tolerance = 1e-10;  // |r_f| <= rtol * reference (the largest initial |r_f| of a step)
  double absolute_tolerance = 0.0;    // ... or |r_f| <= atol
  // ... or a full step with |du| <= increment_tolerance |u|: the residual of a small-
  // strain problem has a rounding floor (|Y| - |xi| cancels) that rtol may sit below.
  double increment_tolerance = 1e-13;
  // ... or stagnation on the rounding floor: `stagnation_window` consecutive steps, each
  // moving u by at most stagnation_increment |u|, that together reduced |r_f| by less
  // than half. An ill-conditioned system (nearly incompressible, stiff inclusions) has a
  // residual floor far above rtol; this ends the iteration there and says so. 0 turns it off.
  int stagnation_window = 3;
  double stagnation_increment = 1e-7;
  // The ceiling on both rules above: they end a load step only when |r_f| <= floor_factor
  // * the rounding floor, measured at u as |r_f(u + e) - r_f(u)| with e_i = +-eps (|u_i| +
  // rounding_length) on the free dofs (what one evaluation of r cannot resolve: the
  // rounding of the positions through the true stiffness, |K| eps |y|, plus the
  // evaluation's own rounding or noise), and at least eps * reference. Small steps above
  // the ceiling mean the step came from a tangent that does not match r or a singular
  // system, not from the floor: Newton iterates on and fails, naming |r| and the ceiling.
  double floor_factor = 100;
  int max_backtracks = 12;            // halvings of the step
  double sufficient_decrease = 1e-4;  // Armijo constant on |r_f|
  LinearSolverOptions linear;
  // Matrix-free Newton-Krylov: the linear systems are solved by preconditioned CG
  // (symmetric) or GMRES through NonlinearSystem::jvp, never forming K. The
  // preconditioner: Jacobi, or the approximate tangent's factorisation, formed once per
  // load step: its cost is amortised over the Krylov iterations.
  bool matrix_free = false;
  MatrixFreePreconditioner matrix_free_preconditioner = MatrixFreePreconditioner::jacobi;
  double krylov_tolerance = 1e-8;  // forcing term: |K du - r| <= tol |r|
  // Eisenstat-Walker forcing (their choice 2, gamma 0.9, exponent 2) for the matrix-
  // free path: solve loosely while far from the solution, tightly near it, never
  // tighter than krylov_tolerance nor than reaching rtol needs. Off: always krylov_tolerance.
  bool adaptive_forcing = true;
  double max_forcing = 1e-2;
  int krylov_max_iterations = 5000;
  int gmres_restart = 60;
  // Called after each converged load step with its solution; returns how many changes
  // it made to the system (e.g. bonds broken). Non-zero: the same load step is solved
  // again from that solution on the changed system, until the hook changes nothing or
  // max_resolves re-solves have not sufficed (then the solve fails, saying so).
  std::function<long long(int step, double load, const Eigen::VectorXd& u)> after_step;
  int max_resolves = 50;
};

struct NewtonRecord {
  int step = 0, iteration = 0;
  int round = 0;                  // re-solves of this load step before this one (after_step)
  double load = 0, residual = 0;  // |r_f| at this iterate
  double step_length = 0;         // line-search factor of the step that led here (0 at iteration 0)
  double increment = 0;           // |du| / |u| of that step
  int linear_iterations = 0;      // Krylov iterations of that step
  double linear_error = 0;
};

struct NewtonResult {
  bool converged = false;
  bool stagnated = false;     // converged by the stagnation rule (the residual floor), not by rtol
  double rounding_floor = 0;  // the last measured rounding floor of |r_f| (0: never needed)
  std::vector<NewtonRecord> history;
  std::string linear_solver;    // the method that solved the last system
  std::string linear_choice;    // why (and any fallback)
  std::string message;          // the failure, when not converged
  std::int64_t unknowns = 0;    // free dofs
  std::int64_t nonzeros = 0;    // of the reduced tangent (0 when matrix-free)
  int resolves = 0;             // load steps solved again after after_step changed the system
  int step_cuts = 0;            // load steps (or parts) bisected after failing (max_step_cuts)
  double assembly_seconds = 0;  // forming tangents (or diagonals, matrix-free)
  double linear_seconds = 0;    // factorisations and linear solves
  int iterations() const { return history.empty() ? 0 : static_cast<int>(history.size()) - 1; }
};

// Solves r(u) = 0 on the free dofs of `dofs`, with the constrained ones at
// load * prescribed, for load = 1/steps .. 1. u holds the initial guess and the
// result. `log` gets one line per iteration and solver messages.
class NewtonSolver {
 public:
  explicit NewtonSolver(NewtonSettings settings, std::function<void(const std::string&)> log = {});
  NewtonResult solve(NonlinearSystem& system, const DofMap& dofs, Eigen::VectorXd& u);

 private:
  bool stagnated(const std::vector<NewtonRecord>& history, int it) const;
  double rounding_floor(NonlinearSystem& system, const DofMap& dofs, const Eigen::VectorXd& u, double load,
                        const Eigen::VectorXd& r, double reference) const;
  NewtonSettings s_;
  std::function<void(const std::string&)> log_;
};

}  // namespace pd
