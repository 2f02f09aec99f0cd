// Viscous damping a = f/m - c v: its part of the velocity Verlet half steps.
#include <fmt/core.h>

#include "effects/inertia.hpp"

namespace pd {

std::string ViscousDamping::describe() const {
  return fmt::format("viscous damping: a = f/m - c v, c = {:.6g}", c_);
}

void ViscousDamping::kick(double h, const std::vector<int>& free, const std::vector<double>& inverse_mass,
                          const std::vector<double>& f, std::vector<double>& v) const {
  for (int i : free) v[i] += h * (f[i] * inverse_mass[i] - c_ * v[i]);
}

void ViscousDamping::final_kick(double h, const std::vector<int>& free,
                                const std::vector<double>& inverse_mass, const std::vector<double>& f,
                                std::vector<double>& v) const {
  const double scale = 1.0 / (1.0 + c_ * h);
  for (int i : free) v[i] = (v[i] + h * f[i] * inverse_mass[i]) * scale;
}

std::unique_ptr<ViscousDamping> make_viscous_damping(const Scene& scene) {
  if (!scene.dynamics || scene.dynamics->damping <= 0) return nullptr;
  return std::make_unique<ViscousDamping>(scene.dynamics->damping);
}

}  // namespace pd
