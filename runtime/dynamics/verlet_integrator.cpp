// The two half steps of velocity Verlet.
#include "dynamics/verlet_integrator.hpp"

namespace pd {

VerletIntegrator::VerletIntegrator(const Inertia& inertia, const ViscousDamping* damping,
                                   std::vector<int> free, double dt)
    : inverse_mass_(inertia.inverse_mass()), damping_(damping), free_(std::move(free)), dt_(dt) {}

void VerletIntegrator::first_half(std::vector<double>& u, std::vector<double>& v,
                                  const std::vector<double>& f) const {
  const double h = 0.5 * dt_;
  if (damping_)
    damping_->kick(h, free_, inverse_mass_, f, v);
  else
    for (int i : free_) v[i] += h * (f[i] * inverse_mass_[i]);
  for (int i : free_) u[i] += dt_ * v[i];
}

void VerletIntegrator::second_half(std::vector<double>& v, const std::vector<double>& f) const {
  const double h = 0.5 * dt_;
  if (damping_)
    damping_->final_kick(h, free_, inverse_mass_, f, v);
  else
    for (int i : free_) v[i] = v[i] + h * f[i] * inverse_mass_[i];
}

}  // namespace pd
