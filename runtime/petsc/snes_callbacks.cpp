// The SNES callbacks (snes_callbacks.hpp).
#include "petsc/snes_callbacks.hpp"

#include <fmt/core.h>

namespace pd {

namespace {
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

}  // namespace

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

}  // namespace pd
