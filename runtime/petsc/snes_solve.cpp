// solve_distributed: SNES Newton with line search on F(x) = -r(x); the Jacobian a shell
// applying the generated tangent-vector product, the preconditioning matrix the
// assembled stiffness of problem.preconditioner; KSP CG (GMRES when not symmetric) with
// PCGAMG and the rigid-body near null space. Any of it can be changed by PETSc options.
#include <fmt/core.h>
#include <petscsnes.h>

#include <cmath>
#include <stdexcept>

#include "petsc/distributed_body.hpp"
#include "petsc/petsc_check.hpp"
#include "solve/distributed_backend.hpp"

namespace pd {

namespace {

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
  Vec previous_iterate = nullptr;
  int step = 0, steps = 1, round = 0;
  NewtonResult* result = nullptr;
  const std::function<void(const std::string&)>* log = nullptr;
  int rank = 0;
  std::string error;  // an exception thrown inside a callback, rethrown after SNESSolve
};

// PETSc is C: an exception must not unwind through it. A callback's exception is kept
// and PETSc told of a failure; solve_distributed throws it once SNESSolve has returned.
template <class Body>
PetscErrorCode guarded(SnesContext& c, Body&& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    if (c.error.empty()) c.error = e.what();
    return PETSC_ERR_USER;
  }
}

// Adds the effects' owned rows of (forces or products) to out: their full-length output
// holds garbage at particles far from this rank, which the owned rows never read.
template <class Add>
void add_effect_rows(SnesContext& c, std::vector<double>& out, Add&& add) {
  if (c.problem->effects.empty()) return;
  const int d = c.body->dim();
  c.e.assign(out.size(), 0.0);
  for (const Effect* eff : c.problem->effects) add(*eff, c.e.data());
  const Partition& part = c.body->partition();
  for (int i = 0; i < part.owned(); ++i) {
    const std::ptrdiff_t p = part.owned_particle(i);
    for (int k = 0; k < d; ++k) out[p * d + k] += c.e[p * d + k];
  }
}

PetscErrorCode form_function(SNES, Vec x, Vec F, void* ctx) {
  auto& c = *static_cast<SnesContext*>(ctx);
  return guarded(c, [&]() -> PetscErrorCode {
    const DistributedProblem& pb = *c.problem;
    c.body->to_local(x, c.u);
    c.body->internal_forces(*pb.tangent, c.u, c.w);
    add_effect_rows(c, c.w, [&](const Effect& e, double* out) { e.add_forces(c.u.data(), c.load, out); });
    for (int p : c.body->local_particles())
      for (int k = 0; k < c.body->dim(); ++k)
        c.w[static_cast<std::ptrdiff_t>(p) * c.body->dim() + k] *= -1;  // F = -r
    c.body->from_local(c.w, F);
    PetscScalar* f;
    const PetscScalar* xa;
    PetscCall(VecGetArray(F, &f));
    PetscCall(VecGetArrayRead(x, &xa));
    const Partition& part = c.body->partition();
    const int d = c.body->dim();
    for (std::size_t j = 0; j < c.constrained_local.size(); ++j) {
      const PetscInt l = c.constrained_local[j];
      const int p = part.owned_particle(static_cast<int>(l / d));
      f[l] = c.dirichlet_scale * (xa[l] - c.target_full[static_cast<std::size_t>(p) * d + l % d]);
    }
    PetscCall(VecRestoreArrayRead(x, &xa));
    PetscCall(VecRestoreArray(F, &f));
    return 0;
  });
}

PetscErrorCode shell_mult(Mat J, Vec v, Vec y) {
  void* ctx;
  PetscCall(MatShellGetContext(J, &ctx));
  auto& c = *static_cast<SnesContext*>(ctx);
  return guarded(c, [&]() -> PetscErrorCode {
    c.body->to_local(v, c.v);
    for (int p : c.body->local_particles())
      for (int k = 0; k < c.body->dim(); ++k) {
        const std::size_t i = static_cast<std::size_t>(p) * c.body->dim() + k;
        if (c.constrained[i]) c.v[i] = 0;
      }
    c.body->tangent_product(*c.problem->tangent, c.linearised, c.v, c.w);
    add_effect_rows(c, c.w, [&](const Effect& e, double* out) {
      e.add_stiffness_product(c.linearised.data(), c.load, c.v.data(), out);
    });
    c.body->from_local(c.w, y);
    PetscScalar* ya;
    const PetscScalar* va;
    PetscCall(VecGetArray(y, &ya));
    PetscCall(VecGetArrayRead(v, &va));
    for (PetscInt l : c.constrained_local) ya[l] = c.dirichlet_scale * va[l];
    PetscCall(VecRestoreArrayRead(v, &va));
    PetscCall(VecRestoreArray(y, &ya));
    return 0;
  });
}

PetscErrorCode form_jacobian(SNES, Vec x, Mat J, Mat P, void* ctx) {
  auto& c = *static_cast<SnesContext*>(ctx);
  return guarded(c, [&]() -> PetscErrorCode {
    c.body->to_local(x, c.linearised);
    c.body->assemble_matrix(*c.problem->preconditioner, c.linearised, P);
    PetscCall(MatZeroRowsColumns(P, static_cast<PetscInt>(c.constrained_rows.size()),
                                 c.constrained_rows.data(), c.dirichlet_scale, nullptr, nullptr));
    PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
    return 0;
  });
}

PetscErrorCode monitor(SNES snes, PetscInt it, PetscReal fnorm, void* ctx) {
  auto& c = *static_cast<SnesContext*>(ctx);
  NewtonRecord rec;
  rec.step = c.step, rec.iteration = static_cast<int>(it), rec.round = c.round, rec.load = c.load,
  rec.residual = fnorm;
  if (it > 0) {
    KSP ksp;
    PetscInt kits = 0;
    PetscCall(SNESGetKSP(snes, &ksp));
    PetscCall(KSPGetIterationNumber(ksp, &kits));
    rec.linear_iterations = static_cast<int>(kits);
  }
  c.result->history.push_back(rec);
  if (c.rank == 0 && *c.log)
    (*c.log)(fmt::format(
        "  load {:.3g} (step {}/{}) iteration {}: |F| = {:.6e}{}", c.load, c.step, c.steps, it, fnorm,
        it > 0 ? fmt::format(", {} Krylov iterations", rec.linear_iterations) : std::string()));
  return 0;
}

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

  SnesContext c;
  c.body = &body, c.problem = &pb, c.result = &result, c.log = &log, c.rank = part.rank,
  c.steps = s.load_steps;
  c.constrained.assign(static_cast<std::size_t>(particles.size()) * d, 0);
  for (int dof : pb.dofs->constrained_dofs()) c.constrained[dof] = 1;
  for (int i = 0; i < part.owned(); ++i)
    for (int k = 0; k < d; ++k)
      if (c.constrained[static_cast<std::size_t>(part.owned_particle(i)) * d + k]) {
        c.constrained_local.push_back(static_cast<PetscInt>(i) * d + k);
        c.constrained_rows.push_back(body.global_dof(part.owned_particle(i), k));
      }

  Vec x = body.create_vector(), r = body.create_vector();
  Mat P = body.create_matrix(*pb.preconditioner->inputs().bonds), J;
  const PetscInt m = static_cast<PetscInt>(part.owned()) * d;
  check(MatCreateShell(PETSC_COMM_WORLD, m, m, PETSC_DETERMINE, PETSC_DETERMINE, &c, &J), "MatCreateShell");
  check(MatShellSetOperation(J, MATOP_MULT, reinterpret_cast<void (*)(void)>(shell_mult)),
        "MatShellSetOperation");
  if (pb.symmetric) {
    check(MatSetOption(J, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
    check(MatSetOption(P, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  }
  {  // The Dirichlet scale from the reference stiffness's diagonal.
    std::vector<double> zero(static_cast<std::size_t>(particles.size()) * d, 0.0);
    body.assemble_matrix(*pb.preconditioner, zero, P);
    Vec diag = body.create_vector();
    PetscReal sum = 0;
    PetscInt n = 0;
    check(MatGetDiagonal(P, diag), "MatGetDiagonal");
    check(VecNorm(diag, NORM_1, &sum), "VecNorm");
    check(VecGetSize(diag, &n), "VecGetSize");
    c.dirichlet_scale = sum > 0 ? sum / n : 1.0;
    VecDestroy(&diag);
  }
  MatNullSpace rigid;
  Vec coords = body.coordinates();
  check(MatNullSpaceCreateRigidBody(coords, &rigid), "MatNullSpaceCreateRigidBody");
  check(MatSetNearNullSpace(P, rigid), "MatSetNearNullSpace");

  SNES snes;
  KSP ksp;
  PC pc;
  check(SNESCreate(PETSC_COMM_WORLD, &snes), "SNESCreate");
  check(SNESSetType(snes, SNESNEWTONLS), "SNESSetType");
  check(SNESSetFunction(snes, r, form_function, &c), "SNESSetFunction");
  check(SNESSetJacobian(snes, J, P, form_jacobian, &c), "SNESSetJacobian");
  check(SNESMonitorSet(snes, monitor, &c, nullptr), "SNESMonitorSet");
  check(SNESSetTolerances(snes, 0.0, s.relative_tolerance, s.increment_tolerance, s.max_iterations, -1),
        "SNESSetTolerances");
  check(SNESGetKSP(snes, &ksp), "SNESGetKSP");
  check(KSPSetType(ksp, pb.symmetric ? KSPCG : KSPGMRES), "KSPSetType");
  check(KSPSetTolerances(ksp, s.krylov_tolerance, PETSC_DEFAULT, PETSC_DEFAULT, s.krylov_max_iterations),
        "KSPSetTolerances");
  check(KSPGetPC(ksp, &pc), "KSPGetPC");
  check(PCSetType(pc, PCGAMG), "PCSetType");
  check(SNESSetFromOptions(snes), "SNESSetFromOptions");  // the scene's and the command line's options win
  {
    KSPType kt;
    PCType pt;
    check(KSPGetType(ksp, &kt), "KSPGetType");
    check(PCGetType(pc, &pt), "PCGetType");
    int ranks = part.ranks;
    result.linear_solver = fmt::format("PETSc {} + {}", kt, pt);
    result.linear_choice = fmt::format(
        "SNES newtonls on {} ranks, the generated tangent-vector product as a shell "
        "matrix, the preconditioner assembled on {} bonds ({})",
        ranks, pb.preconditioner->inputs().bonds->bond_count(),
        pb.preconditioner == pb.tangent ? "the tangent's horizon" : "a shorter horizon");
  }

  Eigen::VectorXd target(u.size());
  for (int step = 1; step <= s.load_steps && result.message.empty(); ++step) {
    c.step = step, c.load = static_cast<double>(step) / s.load_steps, c.round = 0;
    target = u;
    pb.dofs->apply_prescribed(target, c.load);
    c.target_full.assign(target.data(), target.data() + target.size());
    for (;;) {
      pb.dofs->apply_prescribed(u, c.load);
      scatter_owned(body, u, x);
      const PetscErrorCode solved = SNESSolve(snes, nullptr, x);
      if (!c.error.empty()) throw std::runtime_error(c.error);
      check(solved, "SNESSolve");
      SNESConvergedReason reason;
      check(SNESGetConvergedReason(snes, &reason), "SNESGetConvergedReason");
      PetscInt lin = 0;
      check(SNESGetLinearSolveIterations(snes, &lin), "SNESGetLinearSolveIterations");
      gather_all(body, x, u);
      if (reason <= 0) {
        result.message = fmt::format("PETSc SNES did not converge at load {:.3g} (step {}/{}): {}", c.load,
                                     step, s.load_steps, SNESConvergedReasons[reason]);
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
  result.converged = result.message.empty();
  SNESDestroy(&snes);
  MatNullSpaceDestroy(&rigid);
  VecDestroy(&coords);
  MatDestroy(&J);
  MatDestroy(&P);
  VecDestroy(&x);
  VecDestroy(&r);
  return result;
}

}  // namespace pd
