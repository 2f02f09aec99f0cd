// One rank's share of a dynamic run's steps (the PETSc backend's StepExecutor,
// exec/step_executor.hpp), over the serial set-up (the same on every rank): the ghost
// update of u, the forces of the rank's own families summed into their owners, every
// effect's after_step on its own families, global sums over the owned dofs, and rank 0's
// gather of the state for the serial run's files. Checkpoints are then the serial format,
// restartable with any rank count.
#pragma once

#include <mpi.h>
#include <petscvec.h>

#include <vector>

#include "exec/step_executor.hpp"
#include "petsc/distributed_body.hpp"

namespace pd {

class RankSteps final : public StepExecutor {
 public:
  // Refuses (SceneError) tied dofs: a fictitious layer's dof reads its master's u,
  // which a rank holds only when the master is its own or a ghost.
  explicit RankSteps(StepState state);
  ~RankSteps() override;
  RankSteps(const RankSteps&) = delete;
  RankSteps& operator=(const RankSteps&) = delete;

  bool root() const override { return part_.rank == 0; }
  const std::vector<int>& free_dofs() const override { return owned_free_; }
  std::string describe(const std::string& method, const std::string& per_update,
                       const std::string& global_sums) const override;
  void forces(double t, std::vector<double>& f, std::vector<double>& g) override;
  bool after_step() override;
  // Each rank holds the whole model but current u only on its own and ghost dofs: the scene
  // rules refuse a law with history on this backend (input/scene_rules.cpp).
  void commit_history() override;
  void sync() override;
  void gather(const std::vector<std::vector<double>*>& extra) override;
  double sum(double local) const override;
  void sum_in_place(double* values, int count) const override;
  double free_square_sum(const std::vector<double>& values) const override;
  void check_agrees(double value, const std::string& what) const override;
  void check_interrupt(const std::string& where) const override;
  void check_finite(const std::string& message) const override;

 private:
  StepState s_;
  DistributedBody body_;
  const Partition& part_;
  std::vector<int> owned_families_, owned_dofs_, owned_free_, owned_constrained_, foreign_dofs_;
  Vec x_ = nullptr, F_ = nullptr;
  std::vector<double> f_local_;
};

}  // namespace pd
