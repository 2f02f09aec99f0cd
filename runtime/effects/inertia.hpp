// The effects a dynamic run's time integration reads: inertia (the mass of every dof)
// and viscous damping (a = f/m - c v). They add no force to r and no stiffness to K (a
// static solve has neither); the velocity Verlet integrator (dynamics/verlet_integrator.hpp)
// takes the mass from the inertia and leaves the damped part of each half step to the damping.
// Adaptive dynamic relaxation's fictitious density is an inertia too (its D u'' term).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "effects/effect.hpp"
#include "input/scene.hpp"
#include "particles.hpp"

namespace pd {

class Inertia final : public Effect {
 public:
  // mass: m_r per dof; inverse: whether the integrator needs 1/m_r (explicit dynamics).
  Inertia(std::vector<double> mass, bool inverse, std::string description);
  std::string name() const override { return "inertia"; }
  std::string describe() const override { return description_; }
  std::size_t allocated_bytes() const override {
    return (mass_.size() + inverse_mass_.size()) * sizeof(double);
  }
  const std::vector<double>& mass() const { return mass_; }
  const std::vector<double>& inverse_mass() const { return inverse_mass_; }  // empty unless asked for
  // Explicit dynamics: the time step, the Gershgorin stable estimate and the dof that sets it.
  double dt = 0, dt_stable = 0;
  int stable_dof = -1;

 private:
  std::vector<double> mass_, inverse_mass_;
  std::string description_;
};

// Explicit dynamics: m = rho V per dof (rho of each particle's material), and the time
// step: the scene's dt, or safety_factor x the stable estimate from the stiffness row
// sums S_r = sum_c |K_rc| (effects/time_step.hpp).
std::unique_ptr<Inertia> make_inertia(const Scene& scene, const Particles& p,
                                      const std::vector<double>& row_sums);

// Adaptive dynamic relaxation: the fictitious density D_ii = S_i / 4 (the largest row sum
// for a row without stiffness), which makes dt = 1 stable (dynamics/dynamic_relaxation.hpp).
std::unique_ptr<Inertia> make_fictitious_density(const Scene& scene, const std::vector<double>& row_sums);

// Mass-proportional viscous damping a = f/m - c v, c = dynamics.damping > 0 (nullptr
// otherwise). Its part of each velocity Verlet half step, on the free dofs, with h = dt/2:
//   kick:       v += h (f/m - c v)                    (explicit in the damping term)
//   final_kick: v = (v + h f/m) / (1 + c h)           (implicit in it)
class ViscousDamping final : public Effect {
 public:
  explicit ViscousDamping(double c) : c_(c) {}
  std::string name() const override { return "viscous damping"; }
  std::string describe() const override;
  double coefficient() const { return c_; }
  void kick(double h, const std::vector<int>& free, const std::vector<double>& inverse_mass,
            const std::vector<double>& f, std::vector<double>& v) const;
  void final_kick(double h, const std::vector<int>& free, const std::vector<double>& inverse_mass,
                  const std::vector<double>& f, std::vector<double>& v) const;

 private:
  double c_;
};

std::unique_ptr<ViscousDamping> make_viscous_damping(const Scene& scene);

}  // namespace pd
