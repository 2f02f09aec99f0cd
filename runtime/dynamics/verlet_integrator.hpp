// Velocity Verlet (explicit central difference) on the free dofs, with the mass of the
// model's inertia effect and, when the model has one, the viscous damping effect's part
// of the half steps (a = f/m - c v); constrained dofs are set by the caller. One step:
//   first_half:  v += dt/2 (f/m - c v);  u += dt v          (v is now v^{n+1/2})
//   [caller: prescribe constrained dofs at t^{n+1}, break bonds, f = f(u^{n+1}, t^{n+1})]
//   second_half: v = (v + dt/2 f/m) / (1 + c dt/2)           (v^{n+1}, implicit in the damping term)
// Without damping this is the symplectic velocity Verlet scheme: its energy error
// stays bounded (O(dt^2)) instead of drifting.
#pragma once

#include <vector>

#include "effects/inertia.hpp"

namespace pd {

class VerletIntegrator {
 public:
  // inertia: its inverse mass per dof; damping: null without; free: the dofs it moves.
  // Both effects must outlive the integrator.
  VerletIntegrator(const Inertia& inertia, const ViscousDamping* damping, std::vector<int> free, double dt);
  void first_half(std::vector<double>& u, std::vector<double>& v, const std::vector<double>& f) const;
  void second_half(std::vector<double>& v, const std::vector<double>& f) const;
  double dt() const { return dt_; }

 private:
  const std::vector<double>& inverse_mass_;
  const ViscousDamping* damping_;
  std::vector<int> free_;
  double dt_;
};

}  // namespace pd
