// Every solver decision in one place: which path a run takes when the scene says `auto`
// (decided before any matrix is built: building K to measure it would already cost the
// memory the choice is meant to save), which assembled solver the exact nonzero count
// then picks, and what a failed factorisation falls back to.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "input/solver_spec.hpp"

namespace pd {

// Nonzeros of the assembled tangent, estimated from the mean family size. A law with
// states couples all the particles of a family (two-horizon reach), so a particle's row
// holds about the particles within 2 delta, 2^dim L_mean + 1 of them, each a dim x dim
// block; a pairwise law (no states, sparsity_pattern.hpp) only its own family's
// L_mean + 1.
std::int64_t estimated_tangent_nonzeros(int particles, double mean_family_size, int dim,
                                        bool pairwise = false);

// What plan_solver needs to know of the model.
struct ProblemSize {
  int particles = 0;
  double mean_family_size = 0;  // bonds per particle
  int dim = 2;
  double delta_over_h = 0;
  // The preconditioner's mean family size (mean_short_family_size); negative: scaled
  // from mean_family_size by the horizons' volume ratio.
  double short_family_size = -1;
  bool pairwise = false;  // the law has no states: one-horizon pattern (Coupling::pairwise)
};

struct SolverPlan {
  NonlinearMethod nonlinear = NonlinearMethod::newton;
  // automatic here means "assembled": choose_linear_solver decides direct or Krylov on
  // the exact count at the first factorisation.
  LinearMethod linear = LinearMethod::automatic;
  Preconditioner preconditioner = Preconditioner::automatic;
  std::string reason;  // one line for the log and the summary ("solver path")
  // petsc: SNES/KSP/PC over the MPI processes (solve/distributed_backend.hpp); matrix-free
  // here too (the tangent is a shell matrix), with an assembled preconditioning matrix
  // on the horizon min(delta, preconditioner_ratio h).
  Backend backend = Backend::serial;
  bool matrix_free() const { return linear == LinearMethod::matrix_free; }
  // Matrix-free, preconditioned by the factorised stiffness of a shorter horizon.
  bool short_horizon_preconditioner() const {
    return matrix_free() && preconditioner != Preconditioner::diagonal;
  }
};

// Whether plan_solver decides anything from the preconditioner's family size (only
// linear: auto with preconditioner: auto does; counting it is a pass over every bond).
bool plan_needs_short_family_size(const SolverSpec& spec);

// linear != auto, or a preconditioner named with auto: the scene's choice. Else:
//  - estimated K nonzeros <= direct_max_nonzeros: assembled (choose_linear_solver then
//    decides on the exact count);
//  - above, matrix-free Newton-Krylov: preconditioned by the factorised stiffness on
//    the horizon min(delta, preconditioner_ratio h) while its estimate fits
//    preconditioner_max_nonzeros, else by Jacobi (the least memory).
SolverPlan plan_solver(const SolverSpec& spec, const ProblemSize& size);

// The assembled solver for a matrix of this size: a named method as given; automatic:
// a direct solver up to direct_max_nonzeros -- CHOLMOD when symmetric (the caller
// asserts positive definiteness), UMFPACK otherwise -- and a preconditioned Krylov
// method above -- CG with incomplete Cholesky when symmetric, BiCGSTAB with ILUT otherwise.
struct SolverChoice {
  LinearMethod method = LinearMethod::automatic;  // concrete: cholmod, umfpack, cg or bicgstab
  Preconditioner preconditioner = Preconditioner::automatic;
  std::string reason;  // one line for the run log
};
SolverChoice choose_linear_solver(LinearMethod method, Preconditioner preconditioner,
                                  long long direct_max_nonzeros, std::int64_t unknowns, std::int64_t nonzeros,
                                  bool symmetric);

// What to try when this solver's factorisation fails: CHOLMOD (not positive definite)
// -> UMFPACK, CG's incomplete Cholesky (breakdown) -> CG with Jacobi; nothing otherwise.
std::optional<SolverChoice> fallback_after_failure(const SolverChoice& failed);

}  // namespace pd
