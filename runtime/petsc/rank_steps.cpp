// One rank's share of a distributed dynamic step (rank_steps.hpp).
#include "petsc/rank_steps.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

#include "input/yaml_keys.hpp"
#include "interrupt.hpp"
#include "petsc/petsc_check.hpp"
#include "petsc/rank_gather.hpp"
#include "petsc/rank_steps_factory.hpp"

namespace pd {

RankSteps::RankSteps(StepState state)
    : s_(state), body_(state.model.particles, state.model.bonds, PETSC_COMM_WORLD), part_(body_.partition()) {
  const Model& model = s_.model;
  if (model.dofs.tied_count() > 0)
    throw SceneError(s_.scene_file +
                     ": solver.backend: the PETSc backend does not take fictitious layers (multipoint "
                     "constraints) in dynamics: a layer's dof reads a master another rank may not hold; use "
                     "the serial backend");
  const int d = model.particles.dim;
  std::vector<char> constrained(s_.u.size(), 0);
  for (int i : model.dofs.constrained_dofs()) constrained[i] = 1;
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
  x_ = body_.create_vector();
  F_ = body_.create_vector();
}

RankSteps::~RankSteps() {
  VecDestroy(&x_);
  VecDestroy(&F_);
}

std::string RankSteps::describe(const std::string& method, const std::string& per_update,
                                const std::string& global_sums) const {
  return fmt::format(
      "distributed: {} over {} MPI ranks (PETSc), rank 0 owns {} particles and {} ghosts; one ghost "
      "update per {}{}",
      method, part_.ranks, part_.owned(), part_.ghosts.size(), per_update, global_sums);
}

void RankSteps::sync() {
  PetscScalar* a;
  check(VecGetArray(x_, &a), "VecGetArray");
  for (std::size_t k = 0; k < owned_dofs_.size(); ++k) a[k] = s_.u[owned_dofs_[k]];
  check(VecRestoreArray(x_, &a), "VecRestoreArray");
  body_.to_local(x_, s_.u);
}

void RankSteps::forces(double t, std::vector<double>& f, std::vector<double>& g) {
  f.resize(s_.u.size());
  g.assign(s_.u.size(), 0.0);
  body_.internal_forces(bond_families(*s_.model.assembler, "backend petsc"), s_.u, f_local_);
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

// The serial after_step would read u at particles this rank does not hold: each effect
// acts on the rank's own families (their particles and bonds' ends are owned or ghosts).
bool RankSteps::after_step() {
  long long changes = 0;
  for (const auto& e : s_.model.effects) changes += e->after_step(s_.u.data(), FamilyScope{&owned_families_});
  return changes > 0;
}

void RankSteps::commit_history() {
  if (s_.model.has_history())
    throw std::logic_error(
        "RankSteps: a law with history under the PETSc backend (the scene rules refuse it)");
}

void RankSteps::gather(const std::vector<std::vector<double>*>& extra) {
  const Model& model = s_.model;
  const int d = model.particles.dim;
  gather_particle_values(part_, d, s_.u, PETSC_COMM_WORLD);
  if (!s_.v.empty()) gather_particle_values(part_, d, s_.v, PETSC_COMM_WORLD);
  for (std::vector<double>* values : extra) gather_particle_values(part_, d, *values, PETSC_COMM_WORLD);
  if (!model.assembler->intact()) {
    gather_family_alpha(part_, s_.model.bonds, PETSC_COMM_WORLD);
    // Rank 0's other families now have their owners' broken bonds: their moments too
    // (the strain energy of a series row reads every family's).
    if (root()) model.assembler->update_moments();
  }
}

double RankSteps::sum(double local) const {
  double global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
  return global;
}

void RankSteps::sum_in_place(double* values, int count) const {
  MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
}

double RankSteps::free_square_sum(const std::vector<double>& values) const {
  double s = 0;
  for (int i : owned_free_) s += values[i] * values[i];
  return sum(s);
}

void RankSteps::check_agrees(double value, const std::string& what) const {
  double high = 0, low = 0;
  MPI_Allreduce(&value, &high, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  MPI_Allreduce(&value, &low, 1, MPI_DOUBLE, MPI_MIN, PETSC_COMM_WORLD);
  if (high != low)
    throw std::logic_error(fmt::format("the ranks' {} differ ({:.17g} .. {:.17g})", what, low, high));
}

// The ranks agree on a signal every step (one integer all-reduce), so all stop at the
// same step instead of one rank leaving the others waiting in the next ghost update.
void RankSteps::check_interrupt(const std::string& where) const {
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

std::unique_ptr<StepExecutor> make_rank_steps(StepState state) { return std::make_unique<RankSteps>(state); }

}  // namespace pd
