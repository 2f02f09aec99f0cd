// The PETSc backend's step executor as the drivers see it: no PETSc or MPI type here, so
// run/ compiles with or without PETSc (without it, petsc/without_petsc.cpp refuses).
#pragma once

#include <memory>

#include "exec/step_executor.hpp"

namespace pd {

// One rank's share of a dynamic run (petsc/rank_steps.hpp). Needs a PETSc session: `pd run`
// opens one for `solver.backend: petsc`.
std::unique_ptr<StepExecutor> make_rank_steps(StepState state);

}  // namespace pd
