// Inertia: the mass per dof of explicit dynamics (rho V) and of dynamic relaxation (the
// fictitious density), and the explicit time step the mass allows.
#include "effects/inertia.hpp"

#include <fmt/core.h>

#include <algorithm>

#include "effects/time_step.hpp"

namespace pd {

Inertia::Inertia(std::vector<double> mass, bool inverse, std::string description)
    : mass_(std::move(mass)), description_(std::move(description)) {
  if (!inverse) return;
  inverse_mass_.resize(mass_.size());
  for (std::size_t i = 0; i < mass_.size(); ++i) inverse_mass_[i] = 1.0 / mass_[i];
}

std::unique_ptr<Inertia> make_inertia(const Scene& scene, const Particles& p,
                                      const std::vector<double>& row_sums) {
  const DynamicsSpec& dyn = *scene.dynamics;
  std::vector<double> mass(static_cast<std::size_t>(p.size()) * p.dim);
  for (int i = 0; i < p.size(); ++i)
    for (int c = 0; c < p.dim; ++c)
      mass[static_cast<std::size_t>(i) * p.dim + c] = scene.materials[p.material[i]].density * p.volume[i];
  const StableStep st = stable_time_step(row_sums, mass);
  const double dt = dyn.dt > 0 ? dyn.dt : dyn.safety_factor * st.dt;
  auto inertia = std::make_unique<Inertia>(
      std::move(mass), true,
      fmt::format("inertia: density per material, velocity Verlet, dt = {:.6g} ({}; Gershgorin stable "
                  "estimate {:.6g} set by "
                  "particle {})",
                  dt, dyn.dt > 0 ? "fixed" : fmt::format("{} x estimate", dyn.safety_factor), st.dt,
                  st.dof / p.dim));
  inertia->dt = dt;
  inertia->dt_stable = st.dt;
  inertia->stable_dof = st.dof;
  return inertia;
}

std::unique_ptr<Inertia> make_fictitious_density(const Scene& scene, const std::vector<double>& row_sums) {
  std::vector<double> density(row_sums.size());
  double largest = 0;
  for (double r : row_sums) largest = std::max(largest, r);
  for (std::size_t i = 0; i < density.size(); ++i)
    density[i] = 0.25 * (row_sums[i] > 0 ? row_sums[i] : largest);
  auto inertia = std::make_unique<Inertia>(
      std::move(density), false,
      fmt::format(
          "adaptive dynamic relaxation: fictitious density D = sum_j |K_ij| / 4, dt = 1, tolerance {:.3g}",
          scene.dynamics->tolerance));
  inertia->dt = 1;
  return inertia;
}

}  // namespace pd
