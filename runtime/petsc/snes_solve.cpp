// solve_distributed: SNES Newton with line search on F(x) = -r(x); the Jacobian a shell
// applying the generated tangent-vector product, the preconditioning matrix the
// assembled stiffness of problem.preconditioner; KSP CG (GMRES when not symmetric) with
// PCGAMG and the rigid-body near null space. Any of it can be changed by PETSc options.
#include <fmt/core.h>
#include <petscsnes.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "petsc/distributed_body.hpp"
#include "petsc/petsc_check.hpp"
#include "petsc/snes_callbacks.hpp"
#include "solve/distributed_backend.hpp"

namespace pd {

namespace {
// What the Krylov solve reported, and what to try: algebraic multigrid is not a
// preconditioner for every peridynamic system (measured on scenes/: GAMG's smoothed
// aggregation is indefinite on the 1000:1 inclusion, where hypre or unsmoothed aggregation
// converge; no AMG converges on paper 001's OBQ collocation operator, a direct factor does).
std::string linear_failure_reason(KSP ksp) {
  KSPConvergedReason why;
  PetscInt its = 0;
  KSPGetConvergedReason(ksp, &why);
  KSPGetIterationNumber(ksp, &its);
  return fmt::format("{} after {} iterations", KSPConvergedReasons[why], its);
}

std::string linear_failure_hint(KSP ksp) {
  return fmt::format(
      " (the Krylov solve: {}). The preconditioner does not suit this system; try "
      "--petsc-options='-pc_type hypre' or '-pc_gamg_agg_nsmooths 0' (high stiffness contrast), a parallel "
      "direct "
      "factor '-pc_type lu -pc_factor_mat_solver_type mumps' (a non-symmetric or indefinite system such as "
      "quadrature: obq), or the serial backend",
      linear_failure_reason(ksp));
}
}  // namespace

namespace {
// The whole solution on every rank, in the model's order.
void gather_all(DistributedBody& body, Vec x, Eigen::VectorXd& u) {
  VecScatter scatter;
  Vec all;
  check(VecScatterCreateToAll(x, &scatter, &all), "VecScatterCreateToAll");
  check(VecScatterBegin(scatter, x, all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  check(VecScatterEnd(scatter, x, all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  const PetscScalar* a;
  check(VecGetArrayRead(all, &a), "VecGetArrayRead");
  const int d = body.dim();
  const ParticleOrder& o = body.partition().order;
  for (std::size_t k = 0; k < o.order.size(); ++k)
    for (int c = 0; c < d; ++c) u[static_cast<Eigen::Index>(o.order[k]) * d + c] = a[k * d + c];
  check(VecRestoreArrayRead(all, &a), "VecRestoreArrayRead");
  VecScatterDestroy(&scatter);
  VecDestroy(&all);
}

// The owned entries of u (model order) into x.
void scatter_owned(const DistributedBody& body, const Eigen::VectorXd& u, Vec x) {
  PetscScalar* a;
  check(VecGetArray(x, &a), "VecGetArray");
  const int d = body.dim();
  for (int i = 0; i < body.partition().owned(); ++i)
    for (int c = 0; c < d; ++c)
      a[i * d + c] = u[static_cast<Eigen::Index>(body.partition().owned_particle(i)) * d + c];
  check(VecRestoreArray(x, &a), "VecRestoreArray");
}

// What the partition costs: the ghost layer is what every product sends and receives.
// Collective: every rank takes part in the reductions; rank 0 logs.
void log_partition_cost(const Partition& part, const std::function<void(const std::string&)>& log) {
  const int local[2] = {part.owned(), static_cast<int>(part.ghosts.size())};
  int lo[2], hi[2];
  MPI_Allreduce(local, lo, 2, MPI_INT, MPI_MIN, PETSC_COMM_WORLD);
  MPI_Allreduce(local, hi, 2, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
  if (part.rank == 0 && log)
    log(fmt::format(
        "  partition: {} rank(s), Morton order, {}..{} particles and {}..{} ghosts (one horizon) per rank; "
        "at most {:.1f}% of a rank's particles are ghosts",
        part.ranks, lo[0], hi[0], lo[1], hi[1], 100.0 * hi[1] / std::max(lo[0], 1)));
}

// The constrained dofs into c: all of them (model order), and the owned ones as local
// offsets and as PETSc global rows.
void mark_constrained(SnesContext& c, const DistributedProblem& pb, const DistributedBody& body,
                      std::size_t particle_count, int d) {
  const Partition& part = body.partition();
  c.constrained.assign(particle_count * d, 0);
  for (int dof : pb.dofs->constrained_dofs()) c.constrained[dof] = 1;
  for (int i = 0; i < part.owned(); ++i)
    for (int k = 0; k < d; ++k)
      if (c.constrained[static_cast<std::size_t>(part.owned_particle(i)) * d + k]) {
        c.constrained_local.push_back(static_cast<PetscInt>(i) * d + k);
        c.constrained_rows.push_back(body.global_dof(part.owned_particle(i), k));
      }
}

// The Dirichlet scale from the reference stiffness's diagonal (P assembled at u = 0).
double dirichlet_scale(const DistributedBody& body, const DistributedProblem& pb, std::size_t particle_count,
                       int d, Mat P) {
  std::vector<double> zero(particle_count * d, 0.0);
  body.assemble_matrix(*pb.preconditioner, zero, P);
  Vec diag = body.create_vector();
  PetscReal sum = 0;
  PetscInt n = 0;
  check(MatGetDiagonal(P, diag), "MatGetDiagonal");
  check(VecNorm(diag, NORM_1, &sum), "VecNorm");
  check(VecGetSize(diag, &n), "VecGetSize");
  const double scale = sum > 0 ? sum / n : 1.0;
  VecDestroy(&diag);
  return scale;
}

// The SNES and the KSP and PC inside it.
struct SnesHandles {
  SNES snes;
  KSP ksp;
  PC pc;
};

// SNES newtonls with the callbacks on c, tolerances from the settings, KSP CG (GMRES
// when not symmetric) with PCGAMG, Eisenstat-Walker forcing; then the PETSc options.
SnesHandles create_snes(const DistributedProblem& pb, SnesContext& c, Vec r, Mat J, Mat P) {
  const NewtonSettings& s = pb.settings;
  SnesHandles h;
  check(SNESCreate(PETSC_COMM_WORLD, &h.snes), "SNESCreate");
  check(SNESSetType(h.snes, SNESNEWTONLS), "SNESSetType");
  check(SNESSetFunction(h.snes, r, form_function, &c), "SNESSetFunction");
  check(SNESSetJacobian(h.snes, J, P, form_jacobian, &c), "SNESSetJacobian");
  check(SNESMonitorSet(h.snes, monitor, &c, nullptr), "SNESMonitorSet");
  check(SNESSetTolerances(h.snes, 0.0, s.relative_tolerance, s.increment_tolerance, s.max_iterations, -1),
        "SNESSetTolerances");
  check(SNESGetKSP(h.snes, &h.ksp), "SNESGetKSP");
  check(KSPSetType(h.ksp, pb.symmetric ? KSPCG : KSPGMRES), "KSPSetType");
  check(KSPSetTolerances(h.ksp, s.krylov_tolerance, PETSC_DEFAULT, PETSC_DEFAULT, s.krylov_max_iterations),
        "KSPSetTolerances");
  check(KSPGetPC(h.ksp, &h.pc), "KSPGetPC");
  check(PCSetType(h.pc, PCGAMG), "PCSetType");
  if (s.adaptive_forcing) {
    // Eisenstat-Walker forcing as the serial matrix-free path has it (their choice 2,
    // gamma 0.9, exponent 2, at most max_forcing): loose linear solves far from the
    // solution, tight near it. -snes_ksp_ew false turns it off (then krylov_tolerance).
    check(SNESKSPSetUseEW(h.snes, PETSC_TRUE), "SNESKSPSetUseEW");
    check(SNESKSPSetParametersEW(h.snes, 2, s.max_forcing, s.max_forcing, 0.9, 2.0, PETSC_DEFAULT,
                                 PETSC_DEFAULT),
          "SNESKSPSetParametersEW");
  }
  check(SNESSetFromOptions(h.snes), "SNESSetFromOptions");  // the scene's and the command line's options win
  return h;
}

// The linear solver as configured (after the options), into result.
void describe_linear_solver(const SnesHandles& h, const DistributedProblem& pb, const Partition& part,
                            NewtonResult& result) {
  KSPType kt;
  PCType pt;
  check(KSPGetType(h.ksp, &kt), "KSPGetType");
  check(PCGetType(h.pc, &pt), "PCGetType");
  int ranks = part.ranks;
  result.linear_solver = fmt::format("PETSc {} + {}", kt, pt);
  result.linear_choice = fmt::format(
      "SNES newtonls on {} ranks, the generated tangent-vector product as a shell "
      "matrix, the preconditioner assembled on {} bonds ({})",
      ranks, pb.preconditioner->inputs().bonds->bond_count(),
      pb.preconditioner->inputs().bonds == pb.tangent->inputs().bonds ? "the tangent's horizon"
                                                                      : "a shorter horizon");
}

// GAMG is the default; when it fails a linear solve and the options name no
// preconditioner, the load step is solved again once with hypre's BoomerAMG (as the serial
// path falls back from CHOLMOD to UMFPACK). Measured: GAMG's smoothed aggregation is
// indefinite on the 1000:1 inclusion of scenes/inclusion.yaml, where BoomerAMG converges.
bool may_fall_back_to_hypre(const DistributedProblem& pb) {
  PetscBool pc_named = PETSC_FALSE;
  check(PetscOptionsHasName(nullptr, nullptr, "-pc_type", &pc_named), "PetscOptionsHasName");
  // Not for a non-symmetric system (obq collocation): no AMG suits it (hypre's Krylov solve
  // "converged" there and the line search then failed); the failure names a direct factor.
#if defined(PETSC_HAVE_HYPRE)
  bool may_fall_back = !pc_named && pb.symmetric;
#else
  (void)pb;
  bool may_fall_back = false;
#endif
  return may_fall_back;
}

// Switches the preconditioner to hypre BoomerAMG after GAMG failed (why), saying so in result.
void switch_to_hypre(const SnesHandles& h, const std::string& why, NewtonResult& result) {
  check(PCSetType(h.pc, PCHYPRE), "PCSetType");
  KSPType kt;
  check(KSPGetType(h.ksp, &kt), "KSPGetType");
  result.linear_solver = fmt::format("PETSc {} + hypre", kt);
  result.linear_choice += fmt::format("; GAMG failed ({}), hypre BoomerAMG instead", why);
}

// The load steps: SNESSolve each (again after after_step changed the system, or once more
// with hypre when GAMG failed), until one fails (result.message) or all are solved.
void solve_load_steps(const DistributedProblem& pb, const SnesHandles& h, SnesContext& c,
                      DistributedBody& body, Vec x, Eigen::VectorXd& u,
                      const std::function<void(const std::string&)>& log, bool may_fall_back,
                      NewtonResult& result) {
  const NewtonSettings& s = pb.settings;
  const Partition& part = body.partition();
  Eigen::VectorXd target(u.size());
  for (int step = 1; step <= s.load_steps && result.message.empty(); ++step) {
    c.step = step, c.load = s.load_at(step), c.round = 0;
    // A rate-dependent law integrates over the step's share of solver.duration (no cuts here).
    if (s.begin_increment)
      s.begin_increment(s.duration * (step - 1) / s.load_steps, s.duration * step / s.load_steps);
    target = u;
    pb.dofs->apply_prescribed(target, c.load);
    c.target_full.assign(target.data(), target.data() + target.size());
    for (;;) {
      pb.dofs->apply_prescribed(u, c.load);
      const Eigen::VectorXd start = u;  // a retry with another preconditioner starts here
      scatter_owned(body, u, x);
      const PetscErrorCode solved = SNESSolve(h.snes, nullptr, x);
      if (!c.error.empty()) throw std::runtime_error(c.error);
      check(solved, "SNESSolve");
      SNESConvergedReason reason;
      check(SNESGetConvergedReason(h.snes, &reason), "SNESGetConvergedReason");
      PetscInt lin = 0;
      check(SNESGetLinearSolveIterations(h.snes, &lin), "SNESGetLinearSolveIterations");
      gather_all(body, x, u);
      if (reason == SNES_DIVERGED_LINEAR_SOLVE && may_fall_back) {
        may_fall_back = false;
        const std::string why = linear_failure_reason(h.ksp);
        if (part.rank == 0 && log)
          log(fmt::format(
              "  the linear solve with GAMG failed ({}); load step {}/{} again with hypre BoomerAMG", why,
              step, s.load_steps));
        switch_to_hypre(h, why, result);
        u = start;
        continue;
      }
      if (reason <= 0) {
        result.message = fmt::format("PETSc SNES did not converge at load {:.3g} (step {}/{}): {}", c.load,
                                     step, s.load_steps, SNESConvergedReasons[reason]);
        if (reason == SNES_DIVERGED_LINEAR_SOLVE) result.message += linear_failure_hint(h.ksp);
        break;
      }
      if (!s.after_step) break;
      const long long changes = s.after_step(step, c.load, u);
      if (changes == 0) break;
      if (++c.round > s.max_resolves) {
        result.message = fmt::format("load step {}/{} still changing after {} re-solves", step, s.load_steps,
                                     s.max_resolves);
        break;
      }
      ++result.resolves;
    }
  }
}

}  // namespace

NewtonResult solve_distributed(const DistributedProblem& pb, Eigen::VectorXd& u,
                               const std::function<void(const std::string&)>& log) {
  if (!DistributedSession::current()) throw std::logic_error("solve_distributed: no DistributedSession");
  const NewtonSettings& s = pb.settings;
  const Particles& particles = *pb.tangent->inputs().particles;
  const int d = particles.dim;
  DistributedBody body(particles, *pb.tangent->inputs().bonds, PETSC_COMM_WORLD);
  const Partition& part = body.partition();
  NewtonResult result;
  result.unknowns = pb.dofs->free_count();
  log_partition_cost(part, log);

  SnesContext c;
  c.body = &body, c.problem = &pb, c.result = &result, c.log = &log, c.rank = part.rank,
  c.steps = s.load_steps;
  mark_constrained(c, pb, body, static_cast<std::size_t>(particles.size()), d);

  Vec x = body.create_vector(), r = body.create_vector();
  Mat P = body.create_matrix(*pb.preconditioner), J;
  const PetscInt m = static_cast<PetscInt>(part.owned()) * d;
  check(MatCreateShell(PETSC_COMM_WORLD, m, m, PETSC_DETERMINE, PETSC_DETERMINE, &c, &J), "MatCreateShell");
  check(MatShellSetOperation(J, MATOP_MULT, reinterpret_cast<void (*)(void)>(shell_mult)),
        "MatShellSetOperation");
  if (pb.symmetric) {
    check(MatSetOption(J, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
    check(MatSetOption(P, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  }
  c.dirichlet_scale = dirichlet_scale(body, pb, static_cast<std::size_t>(particles.size()), d, P);
  MatNullSpace rigid;
  Vec coords = body.coordinates();
  check(MatNullSpaceCreateRigidBody(coords, &rigid), "MatNullSpaceCreateRigidBody");
  check(MatSetNearNullSpace(P, rigid), "MatSetNearNullSpace");

  SnesHandles h = create_snes(pb, c, r, J, P);
  describe_linear_solver(h, pb, part, result);
  const bool may_fall_back = may_fall_back_to_hypre(pb);

  solve_load_steps(pb, h, c, body, x, u, log, may_fall_back, result);
  result.converged = result.message.empty();
  SNESDestroy(&h.snes);
  MatNullSpaceDestroy(&rigid);
  VecDestroy(&coords);
  MatDestroy(&J);
  MatDestroy(&P);
  VecDestroy(&x);
  VecDestroy(&r);
  return result;
}

}  // namespace pd
