// The boundary compensation factor of paper 002 (section 3.3.3, eqs. 3.59-3.62): a
// particle near a free surface has a truncated horizon, so under the same deformation
// its strain-energy density falls short of an interior particle's ("soft boundary").
// Per particle i,
//
//   beta_s(i) = W_inf(i) / W_bdry(i)
//
// under the trial deformation u = e x (isotropic stretch e; the paper's eq. 3.49), with
// W_bdry the energy density of i's actual family and W_inf that of the full family it
// would have inside an infinite lattice of the same spacing (every lattice offset within
// the quadrature's reach, the quadrature's volume factors, the same influence weights).
// Both come from the law's generated moments and energy kernels (alpha folded to 1, so a
// pre-crack's cut bonds are not compensated): no law-specific formula. A law whose energy
// is normalised by its own weighted volume (Silling, LPS under isotropic stretch) gets
// factors of 1 wherever that normalisation already removes the shortfall.
//
// Applied per bond (eq. 3.62's beta_s inside the bond sum) as the mean of the two ends'
// factors, (beta_s(i) + beta_s(j)) / 2, multiplying Bonds::volume_factor: a bond keeps one
// factor in both families (pairwise symmetry, momentum), and moments, forces, tangent and
// product all see it through V[k] like the quadrature's factors.
#pragma once

#include <vector>

#include "input/quadrature.hpp"
#include "kernel_abi.hpp"
#include "particles.hpp"

namespace pd {

struct CompensationInputs {
  const abi::LawDescriptor* law = nullptr;
  const std::vector<std::vector<double>>* params = nullptr;  // per material, law order
  double delta = 0, h = 0;                                   // horizon, lattice spacing
  Quadrature quadrature = Quadrature::Volume;
  double (*influence)(double r, double delta) = nullptr;
  double stretch = 1e-4;  // e of the trial deformation (the paper's value)
};

// beta_s of every particle. Throws std::invalid_argument when the law has no energy
// kernel and std::runtime_error (naming the particle) when a family's trial energy is not
// positive and finite.
std::vector<double> compensation_factors(const Particles& p, const Bonds& b, const CompensationInputs& in);

// Bonds::volume_factor (created as ones when empty) times (beta[i] + beta[j]) / 2.
void apply_compensation(Bonds& b, const std::vector<double>& beta);

}  // namespace pd
