// The two half steps of velocity Verlet.
#include "dynamics/verlet_integrator.hpp"

namespace pd {

VerletIntegrator::VerletIntegrator(std::vector<double> inverse_mass, std::vector<int> free, double dt, double damping)
    : inverse_mass_(std::move(inverse_mass)), free_(std::move(free)), dt_(dt), damping_(damping) {}

void VerletIntegrator::first_half(std::vector<double>& u, std::vector<double>& v, const std::vector<double>& f) const {
  const double h = 0.5 * dt_;
  for (int i : free_) {
    v[i] += h * (f[i] * inverse_mass_[i] - damping_ * v[i]);
    u[i] += dt_ * v[i];
  }
}

void VerletIntegrator::second_half(std::vector<double>& v, const std::vector<double>& f) const {
  const double h = 0.5 * dt_, scale = 1.0 / (1.0 + damping_ * h);
  for (int i : free_) v[i] = (v[i] + h * f[i] * inverse_mass_[i]) * scale;
}

}  // namespace pd
