// The steps both distributed dynamic loops take on one rank (distributed_explicit.cpp,
// distributed_relaxation.cpp), over the serial run's set-up (run/dynamic_run.hpp, the same
// on every rank): the ghost update of u, the forces of the rank's own families summed into
// their owners, bonds broken on its own families, global sums over the owned dofs, and
// rank 0's gather of the state for the serial run's files. State vectors are full-length
// (model order); each rank keeps its own dofs current and its ghosts after an update.
#pragma once

#include <mpi.h>
#include <petscvec.h>

#include <optional>
#include <vector>

#include "damage/critical_stretch.hpp"
#include "petsc/distributed_body.hpp"

namespace pd {

struct DynamicRun;

class RankSteps {
 public:
  // Refuses (SceneError) tied dofs: a fictitious layer's dof reads its master's u,
  // which a rank holds only when the master is its own or a ghost.
  explicit RankSteps(DynamicRun& run);
  ~RankSteps();
  RankSteps(const RankSteps&) = delete;
  RankSteps& operator=(const RankSteps&) = delete;

  const Partition& partition() const { return part_; }
  bool root() const { return part_.rank == 0; }
  const std::vector<int>& owned_dofs() const { return owned_dofs_; }
  const std::vector<int>& owned_free() const { return owned_free_; }

  // u at the ghosts = their owners' u (the owned entries are the rank's own already).
  void ghost_update();
  // The serial run's forces() at the owned dofs: f = f_int + loads(t); g = the loads on
  // free dofs and -f_int on constrained ones (the reactions' work), zero at foreign dofs.
  void forces(double t, std::vector<double>& f, std::vector<double>& g);
  // The damage effect's after_step on the rank's own families (the serial after_step
  // would read u at particles this rank does not hold). Moments follow the broken bonds.
  bool break_bonds();
  // Rank 0's u, v (when a dynamic run has one) and alpha = the owners'.
  void gather();
  double sum(double local) const;
  // The sum over the ranks of the squares of `values` at their owned free dofs.
  double free_square_sum(const std::vector<double>& values) const;
  // The ranks agree on a signal every step (one integer all-reduce), so all stop at the
  // same step instead of one rank leaving the others waiting in the next ghost update.
  void agree_on_interrupt(const std::string& where) const;
  // Throws on every rank when a value of u at an owned dof is not finite on any rank.
  void check_finite(const std::string& message) const;

 private:
  DynamicRun& s_;
  DistributedBody body_;
  const Partition& part_;
  std::vector<int> owned_families_, owned_dofs_, owned_free_, owned_constrained_, foreign_dofs_;
  std::optional<CriticalStretchDamage> damage_;
  Vec x_ = nullptr, F_ = nullptr;
  std::vector<double> f_local_;
};

}  // namespace pd
