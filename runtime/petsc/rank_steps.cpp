// One rank's share of a distributed dynamic step (rank_steps.hpp).
#include "petsc/rank_steps.hpp"

#include <cmath>
#include <stdexcept>

#include "input/yaml_keys.hpp"
#include "interrupt.hpp"
#include "petsc/petsc_check.hpp"
#include "petsc/rank_gather.hpp"
#include "run/dynamic_run.hpp"

namespace pd {

RankSteps::RankSteps(DynamicRun& run)
    : s_(run), body_(run.model.particles, run.model.bonds, PETSC_COMM_WORLD), part_(body_.partition()) {
  if (s_.model.dofs.tied_count() > 0)
    throw SceneError(run.scene.file + ": solver.backend: the PETSc backend does not take fictitious layers (multipoint "
                     "constraints) in dynamics: a layer's dof reads a master another rank may not hold; use the serial backend");
  const int d = s_.model.particles.dim;
  std::vector<char> constrained(s_.u.size(), 0);
  for (int i : s_.model.dofs.constrained_dofs()) constrained[i] = 1;
  for (int i = 0; i < part_.owned(); ++i) {
    const int p = part_.owned_particle(i);
    owned_families_.push_back(p);
    for (int c = 0; c < d; ++c) {
      const int dof = p * d + c;
      owned_dofs_.push_back(dof);
      (constrained[dof] ? owned_constrained_ : owned_free_).push_back(dof);
    }
  }
  // Every dof a rank may hold besides its own: what the work's load vector must not count.
  std::vector<char> owned(s_.u.size(), 0);
  for (int dof : owned_dofs_) owned[dof] = 1;
  for (std::size_t i = 0; i < owned.size(); ++i)
    if (!owned[i]) foreign_dofs_.push_back(static_cast<int>(i));
  if (s_.model.damage)
    damage_.emplace(s_.model.particles, s_.model.bonds, s_.model.damage->s0(), s_.model.damage->tension_only());
  x_ = body_.create_vector();
  F_ = body_.create_vector();
}

RankSteps::~RankSteps() {
  VecDestroy(&x_);
  VecDestroy(&F_);
}

void RankSteps::ghost_update() {
  PetscScalar* a;
  check(VecGetArray(x_, &a), "VecGetArray");
  for (std::size_t k = 0; k < owned_dofs_.size(); ++k) a[k] = s_.u[owned_dofs_[k]];
  check(VecRestoreArray(x_, &a), "VecRestoreArray");
  body_.to_local(x_, s_.u);
}

void RankSteps::forces(double t, std::vector<double>& f, std::vector<double>& g) {
  f.resize(s_.u.size());
  g.assign(s_.u.size(), 0.0);
  body_.internal_forces(*s_.model.assembler, s_.u, f_local_);
  body_.from_local(f_local_, F_);
  const PetscScalar* a;
  check(VecGetArrayRead(F_, &a), "VecGetArrayRead");
  for (std::size_t k = 0; k < owned_dofs_.size(); ++k) f[owned_dofs_[k]] = a[k];
  check(VecRestoreArrayRead(F_, &a), "VecRestoreArrayRead");
  for (const auto& e : s_.model.effects) e->add_forces(s_.u.data(), t, g.data());
  for (int i : foreign_dofs_) g[i] = 0.0;
  for (int i : owned_dofs_) f[i] += g[i];
  for (int i : owned_constrained_) g[i] = g[i] - f[i];
}

bool RankSteps::break_bonds() {
  if (!damage_ || damage_->break_family_bonds(s_.u.data(), owned_families_) == 0) return false;
  s_.model.assembler->update_moments();
  return true;
}

void RankSteps::gather() {
  const int d = s_.model.particles.dim;
  gather_particle_values(part_, d, s_.u, PETSC_COMM_WORLD);
  if (!s_.v.empty()) gather_particle_values(part_, d, s_.v, PETSC_COMM_WORLD);
  if (!s_.model.assembler->intact()) {
    gather_family_alpha(part_, s_.model.bonds, PETSC_COMM_WORLD);
    // Rank 0's other families now have their owners' broken bonds: their moments too
    // (the strain energy of a series row reads every family's).
    if (root()) s_.model.assembler->update_moments();
  }
}

double RankSteps::sum(double local) const {
  double global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
  return global;
}

double RankSteps::free_square_sum(const std::vector<double>& values) const {
  double s = 0;
  for (int i : owned_free_) s += values[i] * values[i];
  return sum(s);
}

void RankSteps::agree_on_interrupt(const std::string& where) const {
  int local_signal = interrupt_signal(), signal = 0;
  MPI_Allreduce(&local_signal, &signal, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
  if (signal == 0) return;
  if (local_signal == 0) request_interrupt(signal);
  throw_if_interrupted(where);
}

void RankSteps::check_finite(const std::string& message) const {
  int finite = 1, all_finite = 0;
  for (int i : owned_dofs_) finite = finite && std::isfinite(s_.u[i]);
  MPI_Allreduce(&finite, &all_finite, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD);
  if (!all_finite) throw std::runtime_error(message);
}

}  // namespace pd
