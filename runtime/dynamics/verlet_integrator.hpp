// Velocity Verlet (explicit central difference) with optional mass-proportional damping
// a = f/m - c v, on the free dofs; constrained dofs are set by the caller. One step:
//   first_half:  v += dt/2 (f/m - c v);  u += dt v          (v is now v^{n+1/2})
//   [caller: prescribe constrained dofs at t^{n+1}, break bonds, f = f(u^{n+1}, t^{n+1})]
//   second_half: v = (v + dt/2 f/m) / (1 + c dt/2)           (v^{n+1}, implicit in the damping term)
// Without damping this is the symplectic velocity Verlet scheme: its energy error
// stays bounded (O(dt^2)) instead of drifting.
#pragma once

#include <vector>

namespace pd {

class VerletIntegrator {
 public:
  // inverse_mass per dof; free: the dofs the integrator moves.
  VerletIntegrator(std::vector<double> inverse_mass, std::vector<int> free, double dt, double damping);
  void first_half(std::vector<double>& u, std::vector<double>& v, const std::vector<double>& f) const;
  void second_half(std::vector<double>& v, const std::vector<double>& f) const;
  double dt() const { return dt_; }

 private:
  std::vector<double> inverse_mass_;
  std::vector<int> free_;
  double dt_, damping_;
};

}  // namespace pd
