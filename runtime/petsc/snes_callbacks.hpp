// The SNES callbacks of solve_distributed and the state they share: the residual
// F(x) = -r(x) with Dirichlet rows, the shell tangent's product, the preconditioning
// matrix's assembly and the monitor that records Newton's history.
#pragma once

#include <petscsnes.h>

#include <functional>
#include <string>
#include <vector>

#include "petsc/distributed_body.hpp"
#include "solve/distributed_backend.hpp"

namespace pd {

// Dirichlet rows: F_d = s (x_d - t_d) and J e_d = s e_d, with the columns zeroed too
// (MatZeroRowsColumns), so J stays symmetric. s is the mean diagonal of the stiffness:
// a unit diagonal among entries of order E h^dim would skew the spectrum AMG sees.
struct SnesContext {
  DistributedBody* body = nullptr;
  const DistributedProblem* problem = nullptr;
  double load = 0, dirichlet_scale = 1;
  std::vector<char> constrained;            // [n*dim] model order
  std::vector<PetscInt> constrained_rows;   // owned, PETSc global dofs
  std::vector<PetscInt> constrained_local;  // the same as offsets into the owned array
  std::vector<double> target_full;          // prescribed values at this load, model order
  std::vector<double> u, v, w, e;           // full-length work arrays
  std::vector<double> linearised;           // the Jacobian's point (the shell's u)
  int step = 0, steps = 1, round = 0;
  NewtonResult* result = nullptr;
  const std::function<void(const std::string&)>* log = nullptr;
  int rank = 0;
  std::string error;  // an exception thrown inside a callback, rethrown after SNESSolve
};

// Each callback catches what the body throws (PETSc is C: an exception must not unwind
// through it), keeps it in SnesContext::error and reports a failure to PETSc;
// solve_distributed throws it once SNESSolve has returned.
PetscErrorCode form_function(SNES, Vec x, Vec F, void* ctx);
PetscErrorCode shell_mult(Mat J, Vec v, Vec y);
PetscErrorCode form_jacobian(SNES, Vec x, Mat J, Mat P, void* ctx);
PetscErrorCode monitor(SNES snes, PetscInt it, PetscReal fnorm, void* ctx);

}  // namespace pd
