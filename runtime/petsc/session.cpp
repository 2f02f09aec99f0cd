// PetscInitialize/PetscFinalize for a run, with the scene's and the command line's options.
#include <petscsys.h>

#include "petsc/petsc_check.hpp"
#include "solve/distributed_backend.hpp"

namespace pd {

namespace {
const DistributedSession* g_session = nullptr;
}

bool distributed_backend_available() { return true; }

DistributedSession::DistributedSession(const std::vector<std::string>& options) {
  if (g_session) throw std::logic_error("DistributedSession: one per process");
  // No argv: pd's own command line is CLI11's; PETSc options come as strings (and from
  // PETSC_OPTIONS, which PetscInitialize reads itself).
  check(PetscInitializeNoArguments(), "PetscInitialize");
  for (const std::string& o : options)
    if (!o.empty()) check(PetscOptionsInsertString(nullptr, o.c_str()), ("options '" + o + "'").c_str());
  // PetscInitialize starts the event log only for a -log_view it saw itself (argv,
  // PETSC_OPTIONS); given here, PetscFinalize would fail on it after the run ("Must use
  // -log_view or PetscLogDefaultBegin() before calling this routine").
  PetscBool log_view = PETSC_FALSE;
  check(PetscOptionsHasName(nullptr, nullptr, "-log_view", &log_view), "PetscOptionsHasName");
  if (log_view) check(PetscLogDefaultBegin(), "PetscLogDefaultBegin");
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank_);
  MPI_Comm_size(PETSC_COMM_WORLD, &size_);
  g_session = this;
}

DistributedSession::~DistributedSession() {
  g_session = nullptr;
  PetscFinalize();
}

const DistributedSession* DistributedSession::current() { return g_session; }

}  // namespace pd
