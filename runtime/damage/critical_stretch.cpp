// Critical-stretch bond breaking and damage per particle.
#include "damage/critical_stretch.hpp"

#include <fmt/core.h>

#include <cmath>
#include <numbers>

#include "damage/bond_fracture_energy.hpp"

namespace pd {

double critical_stretch(const DamageSpec& spec, const MaterialSpec& material, int dim, double delta,
                        const abi::LawDescriptor& law, const std::vector<double>& params,
                        double (*weight)(double r, double delta)) {
  if (spec.critical_stretch > 0) return spec.critical_stretch;
  if (is_pairwise_law(law) && law.intact.energy != nullptr)
    return std::sqrt(spec.fracture_energy /
                     pairwise_fracture_energy_per_stretch2(law, params, weight, delta));
  const IsotropicElastic e = dim == 2 && material.plane == PlaneAssumption::Stress
                                 ? material.elastic.plane_stress_equivalent()
                                 : material.elastic;
  if (dim == 2) {
    const double kappa = e.lambda + e.G;  // the plane-strain 2D bulk modulus
    return std::sqrt(std::numbers::pi * spec.fracture_energy / (3 * kappa * delta));
  }
  return std::sqrt(5 * spec.fracture_energy / (9 * e.K * delta));
}

std::string critical_stretch_origin(const DamageSpec& spec, int dim, const abi::LawDescriptor& law) {
  if (spec.fracture_energy <= 0) return "";
  if (is_pairwise_law(law) && law.intact.energy != nullptr)
    return fmt::format(" (from G0 = {:.6g}, the bond sum of law {}'s micromodulus)", spec.fracture_energy,
                       law.name);
  return fmt::format(" (from G0 = {:.6g}, PMB {}D formula: an approximation for a state-based law)",
                     spec.fracture_energy, dim);
}

CriticalStretchDamage::CriticalStretchDamage(const Particles& particles, Bonds& bonds, double s0,
                                             bool tension_only)
    : p_(particles), b_(bonds), s0_(s0), tension_only_(tension_only) {}

namespace {
// Breaks bond entry e of family a when over the limit; true when it broke. Y = (x_b +
// u_b) - (x_a + u_a): the two families subtract the same two numbers, so their |Y|
// agree bit for bit and both copies of a bond break together, whichever process holds them.
inline bool break_if_over(const Particles& p, Bonds& bonds, const double* u, double s0, bool tension_only,
                          int a, int e) {
  if (bonds.alpha[e] == 0.0) return false;
  const int d = p.dim, b = bonds.neighbor[e];
  double l2 = 0;
  for (int c = 0; c < d; ++c) {
    const std::size_t ia = static_cast<std::size_t>(a) * d + c, ib = static_cast<std::size_t>(b) * d + c;
    const double y = (p.x[ib] + u[ib]) - (p.x[ia] + u[ia]);
    l2 += y * y;
  }
  const double s = (std::sqrt(l2) - bonds.length[e]) / bonds.length[e];
  if (!(s > s0 || (!tension_only && -s > s0))) return false;
  bonds.alpha[e] = 0.0;
  return true;
}
}  // namespace

int CriticalStretchDamage::break_bonds(const double* u) {
  const int n = p_.size();
  int broken = 0;
#pragma omp parallel for reduction(+ : broken) schedule(static)
  for (int a = 0; a < n; ++a)
    for (int e = b_.offsets[a]; e < b_.offsets[a + 1]; ++e)
      if (break_if_over(p_, b_, u, s0_, tension_only_, a, e)) broken += b_.neighbor[e] < a ? 0 : 1;
  return broken;
}

int CriticalStretchDamage::break_family_bonds(const double* u, const std::vector<int>& families) {
  int broken = 0;
  for (int a : families)
    for (int e = b_.offsets[a]; e < b_.offsets[a + 1]; ++e)
      broken += break_if_over(p_, b_, u, s0_, tension_only_, a, e) ? 1 : 0;
  return broken;
}

std::string CriticalStretchDamage::describe() const {
  return fmt::format("damage: critical-stretch bond breaking (PMB), s0 = {:.6g}, {}", s0_,
                     tension_only_ ? "tension only" : "tension and compression");
}

std::vector<double> particle_damage(const Bonds& bonds) {
  const int n = bonds.particle_count();
  std::vector<double> damage(static_cast<std::size_t>(n), 0.0);
  for (int p = 0; p < n; ++p) {
    int broken = 0;
    for (int e = bonds.offsets[p]; e < bonds.offsets[p + 1]; ++e) broken += bonds.alpha[e] == 0.0;
    damage[p] = bonds.family_size(p) ? static_cast<double>(broken) / bonds.family_size(p) : 0.0;
  }
  return damage;
}

long long broken_bond_count(const Bonds& bonds) {
  long long n = 0;
  for (double a : bonds.alpha) n += a == 0.0;
  return n / 2;
}

}  // namespace pd
