// Damage evolution: critical-stretch bond breaking of the prototype microelastic
// brittle (PMB) model. A bond whose stretch s = (|Y| - |xi|) / |xi| exceeds s0 breaks
// for good (alpha = 0 in both families); by default only in tension (s > s0), with
// tension_only = false also in compression (|s| > s0). Created only when the scene has
// a `damage` section: a scene without one allocates nothing here.
#pragma once

#include <string>
#include <vector>

#include "input/scene.hpp"
#include "kernel_abi.hpp"
#include "particles.hpp"

namespace pd {

// The critical stretch of a damage spec: given directly, or from the fracture energy G0.
// For a pairwise (bond-based) law, from that law's own micromodulus, read off its energy
// kernel (damage/bond_fracture_energy.hpp): s0 = sqrt(G0 / g), G0 = g s0^2; for the
// conical micromodulus this is G0 = 2.4 kappa delta s0^2 / pi, not the constant one's
// 3 kappa delta s0^2 / pi. For a state-based law no bond sum gives G0 (a broken bond's
// energy depends on the dilatation of both families); s0 then comes from the PMB
// relations of the constant micromodulus matched to the same bulk modulus
// (docs/laws.md: c = 12 kappa / (pi delta^3) in 2D, 18 K / (pi delta^4) in 3D):
//   2D: s0 = sqrt(pi G0 / (3 kappa delta)), kappa = lambda + G of the (plane-strain
//       equivalent) material; 3D: s0 = sqrt(5 G0 / (9 K delta)) (Silling & Askari 2005),
// an approximation the run log names. G0 is the work to break every bond crossing a
// unit crack length (area in 3D). `params` are the law's parameters for `material`.
double critical_stretch(const DamageSpec& spec, const MaterialSpec& material, int dim, double delta,
                        const abi::LawDescriptor& law, const std::vector<double>& params,
                        double (*weight)(double r, double delta));
// For the run log: "" when s0 was given, " (from G0 = ..., the law's micromodulus)" or
// " (from G0 = ..., PMB 2D formula: an approximation for a state-based law)" otherwise.
std::string critical_stretch_origin(const DamageSpec& spec, int dim, const abi::LawDescriptor& law);

class CriticalStretchDamage {
 public:
  CriticalStretchDamage(const Particles& particles, Bonds& bonds, double s0, bool tension_only);
  // Breaks every intact bond over the limit at displacement u; returns how many bonds
  // broke (each counted once, not per family). Deterministic and thread-count independent.
  int break_bonds(const double* u);
  // The same rule on the bonds of the listed families only (a rank's own families under
  // MPI: the damage effect with a FamilyScope, petsc/rank_steps.cpp). Returns the bond entries broken, each
  // family's copy counted (its partner copy is in another family, maybe on another rank).
  int break_family_bonds(const double* u, const std::vector<int>& families);
  double s0() const { return s0_; }
  bool tension_only() const { return tension_only_; }
  std::string describe() const;

 private:
  const Particles& p_;
  Bonds& b_;
  double s0_;
  bool tension_only_;
};

// Damage per particle: the broken fraction of its family (0 intact .. 1 all broken).
std::vector<double> particle_damage(const Bonds& bonds);
// Broken bonds, each counted once.
long long broken_bond_count(const Bonds& bonds);

}  // namespace pd
