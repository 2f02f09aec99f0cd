// The distributed backend (`solver.backend: petsc`), as the serial runtime sees it: an
// MPI/PETSc session for the run and one static solve over the model. No PETSc type
// appears here, so the serial runtime compiles the same with or without PETSc; the
// implementation is runtime/petsc/ (or petsc/without_petsc.cpp, which refuses clearly).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "assembly/assembler.hpp"
#include "constraints/dof_map.hpp"
#include "effects/effect.hpp"
#include "solve/newton.hpp"

namespace pd {

// True when this build has the PETSc backend.
bool distributed_backend_available();

// Whether this process was started by an MPI launcher with more than one process
// (OpenMPI's, MPICH's or Slurm's environment), without initialising MPI.
int launched_process_count();

// PETSc (and MPI) for the life of the object: one per run. `options` are PETSc options
// ("-ksp_monitor -pc_type hypre"), inserted in order: the scene's first, then the
// command line's, so the command line wins; PETSC_OPTIONS in the environment works too.
// Throws std::runtime_error when the build has no PETSc.
class DistributedSession {
 public:
  explicit DistributedSession(const std::vector<std::string>& options);
  ~DistributedSession();
  DistributedSession(const DistributedSession&) = delete;
  DistributedSession& operator=(const DistributedSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  // The session of this process, or null outside one.
  static const DistributedSession* current();

 private:
  int rank_ = 0, size_ = 1;
};

// One static solve on every rank of the session: each rank owns a contiguous block of
// the particles in space-filling-curve order and runs the kernels on its own families.
struct DistributedProblem {
  const FamilyAssembler* tangent = nullptr;  // the law: residual and tangent-vector product
  // The assembled preconditioning matrix's law (the tangent's own, or a shorter horizon).
  const FamilyAssembler* preconditioner = nullptr;
  std::vector<const Effect*> effects;  // forces and tangent-vector products (not in the matrix)
  const DofMap* dofs = nullptr;        // Dirichlet conditions, as the serial path has them
  bool symmetric = true;               // CG when true, GMRES otherwise
  NewtonSettings settings;             // load steps, tolerances, Krylov limits, after_step
};

// Solves r(u) = 0 with PETSc's SNES (Newton, line search) and KSP/PC; u (every rank, in
// the model's particle order) holds the initial guess and, on return, the solution on
// every rank. Log lines come from rank 0 only.
NewtonResult solve_distributed(const DistributedProblem& problem, Eigen::VectorXd& u,
                               const std::function<void(const std::string&)>& log);

}  // namespace pd
