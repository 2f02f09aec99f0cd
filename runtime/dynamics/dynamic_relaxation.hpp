// Adaptive dynamic relaxation (ADR) for statics: paper 003 eqs. (23)-(28), after Kilic &
// Madenci (2010), whose formulas paper 002 chapter 4 also uses.
//   D u'' + c D u' = F(u)                                              (23)
//   v^{n+1/2} = ((2 - c^n dt) v^{n-1/2} + 2 dt D^-1 F^n) / (2 + c^n dt)  (27)
//   u^{n+1}   = u^n + dt v^{n+1/2}                                     (28)
// with dt = 1, the fictitious diagonal density D_ii = (1/4) dt^2 sum_j |K_ij| (the
// Gershgorin bound of time_step.hpp: lambda_max(D^-1 K) <= 4, so dt = 1 is stable),
// the first step v^{1/2} = dt D^-1 F^0 / 2, and the adaptive damping coefficient
//   c^n = 2 sqrt((u^T K1 u) / (u^T u)),  K1_ii = -(F_i^n - F_i^{n-1}) / (D_ii dt v_i^{n-1/2})
// (the local diagonal stiffness estimate; c^n = 0 when u^T K1 u <= 0, and c^n dt is
// capped at 2 so the velocity is never reversed). F is the out-of-balance force
// (internal plus external); the iteration stops when |F_free| <= tolerance x reference.
#pragma once

#include <functional>
#include <vector>

namespace pd {

class AdaptiveDynamicRelaxation {
 public:
  // density: D_ii per dof (only free dofs are read), read in place (the model's
  // fictitious-density effect, effects/inertia.hpp, which must outlive the iteration);
  // free: the dofs it moves.
  // sum: over processes, in place, of the damping's two sums over `free` (distributed runs
  // pass each rank's own free dofs and an all-reduce; none: one process holds every dof).
  using Sum = std::function<void(double* values, int count)>;
  AdaptiveDynamicRelaxation(const std::vector<double>& density, std::vector<int> free, Sum sum = {});
  // One iteration from the force F^n at u^n: updates v (to v^{n+1/2}) and u (to u^{n+1}).
  void step(const std::vector<double>& F, std::vector<double>& u);
  double damping() const { return c_; }
  int iterations() const { return n_; }
  // State for a checkpoint: velocity and previous force (restored with restore()).
  const std::vector<double>& velocity() const { return v_; }
  const std::vector<double>& previous_force() const { return f_prev_; }
  void restore(int iterations, std::vector<double> v, std::vector<double> f_prev);

 private:
  const std::vector<double>& D_;
  std::vector<int> free_;
  Sum sum_;
  std::vector<double> v_, f_prev_;
  double c_ = 0;
  int n_ = 0;
};

}  // namespace pd
